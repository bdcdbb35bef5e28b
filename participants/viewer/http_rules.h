// The viewer's HTTP rules as pure functions, apart from the sockets: which
// request targets map to which static files, their content types, and which
// WebSocket upgrades are accepted.
#pragma once

#include <chrono>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace turf::viewer {

// The file under the web root that `target` names ("/" is "index.html"), or
// nullopt for anything else: a query is ignored; only [A-Za-z0-9._-] path
// segments, none starting with '.', at most 4 deep and 200 bytes, so no
// target can leave the web root.
std::optional<std::string> StaticFile(std::string_view target);

// The camera panel's image target (camera_frames.h): "/camera/red_1/camera.jpg?t=12" -> {red_1, camera}; a query
// is ignored; both names [A-Za-z0-9_], 1..64 bytes; nullopt for anything else.
struct CameraTarget {
  std::string robot;
  std::string camera;
};
std::optional<CameraTarget> ParseCameraTarget(std::string_view target);

// The Content-Type of a served file, by extension.
std::string ContentType(std::string_view path);

// Cross-site WebSocket hijacking guard. A browser always sends Origin; a page
// from another site (e.g. a web page the user happens to have open) must not
// drive the simulator, so the Origin's host:port must equal the Host header.
// A request without Origin (not from a browser) is allowed. With
// `loopback_only` (the default 127.0.0.1 binding) the Host must also be a
// loopback name, which stops DNS-rebinding pages; on another binding it must
// be an IP address, localhost or one of `names` (this machine's name and
// --allow-host's, any case): a rebinding site's own name is none of them.
bool UpgradeAllowed(std::string_view host, std::string_view origin, bool loopback_only,
                    const std::vector<std::string>& names = {});
// The names a page on a non-loopback binding may use besides addresses: `extra` (--allow-host), this machine's
// host name and that name with ".local" (mDNS).
std::vector<std::string> PageHostNames(const std::vector<std::string>& extra);

// At most `per_second` messages in any one-second window; more are refused.
class RateLimit {
 public:
  explicit RateLimit(int per_second) : per_second_(per_second) {}
  bool Allow(std::chrono::steady_clock::time_point now);

 private:
  int per_second_;
  int count_ = 0;
  std::chrono::steady_clock::time_point window_start_{};
};

}  // namespace turf::viewer
