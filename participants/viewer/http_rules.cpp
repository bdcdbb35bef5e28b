#include "participants/viewer/http_rules.h"

#include <unistd.h>

#include <cctype>

namespace turf::viewer {

namespace {

bool SegmentChar(char c) {
  return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') || c == '.' || c == '_' || c == '-';
}

bool EndsWith(std::string_view s, std::string_view suffix) {
  return s.size() >= suffix.size() && s.substr(s.size() - suffix.size()) == suffix;
}

// "host:port" -> "host" ("[::1]:8080" -> "[::1]").
std::string_view HostName(std::string_view host) {
  if (!host.empty() && host.front() == '[') {
    const size_t close = host.find(']');
    return close == std::string_view::npos ? host : host.substr(0, close + 1);
  }
  const size_t colon = host.rfind(':');
  return colon == std::string_view::npos ? host : host.substr(0, colon);
}

bool Token(std::string_view s) {
  if (s.empty() || s.size() > 64) return false;
  for (char c : s)
    if (!(std::isalnum(static_cast<unsigned char>(c)) || c == '_')) return false;
  return true;
}

// An IPv4 address in dots or a bracketed IPv6 one: no DNS lookup, so no rebinding.
bool IpLiteral(std::string_view name) {
  if (name.size() >= 2 && name.front() == '[' && name.back() == ']') return true;
  if (name.empty()) return false;
  for (char c : name)
    if (!(std::isdigit(static_cast<unsigned char>(c)) || c == '.')) return false;
  return true;
}

bool SameName(std::string_view a, std::string_view b) {
  if (a.size() != b.size()) return false;
  for (size_t i = 0; i < a.size(); ++i)
    if (std::tolower(static_cast<unsigned char>(a[i])) != std::tolower(static_cast<unsigned char>(b[i]))) return false;
  return true;
}

bool NamedHost(std::string_view name, const std::vector<std::string>& names) {
  if (IpLiteral(name) || SameName(name, "localhost")) return true;
  for (const std::string& n : names)
    if (SameName(name, n)) return true;
  return false;
}

}  // namespace

std::optional<std::string> StaticFile(std::string_view target) {
  const size_t query = target.find('?');
  if (query != std::string_view::npos) target = target.substr(0, query);
  if (target.empty() || target.front() != '/' || target.size() > 200) return std::nullopt;
  if (target == "/") return std::string("index.html");
  std::string out;
  int depth = 0;
  size_t start = 1;
  while (start <= target.size()) {
    size_t end = target.find('/', start);
    if (end == std::string_view::npos) end = target.size();
    const std::string_view segment = target.substr(start, end - start);
    if (segment.empty() || segment.front() == '.' || ++depth > 4) return std::nullopt;
    for (char c : segment)
      if (!SegmentChar(c)) return std::nullopt;
    if (!out.empty()) out += '/';
    out += segment;
    start = end + 1;
  }
  return out;
}

std::string ContentType(std::string_view path) {
  if (EndsWith(path, ".html")) return "text/html; charset=utf-8";
  if (EndsWith(path, ".js")) return "text/javascript; charset=utf-8";
  if (EndsWith(path, ".css")) return "text/css; charset=utf-8";
  if (EndsWith(path, ".json")) return "application/json";
  if (EndsWith(path, ".svg")) return "image/svg+xml";
  if (EndsWith(path, ".png")) return "image/png";
  if (EndsWith(path, ".ico")) return "image/x-icon";
  return "application/octet-stream";
}

std::vector<std::string> PageHostNames(const std::vector<std::string>& extra) {
  std::vector<std::string> names = extra;
  char host[256] = {};
  if (gethostname(host, sizeof(host) - 1) == 0 && host[0] != '\0') {
    names.emplace_back(host);
    names.push_back(std::string(host) + ".local");
  }
  return names;
}

bool UpgradeAllowed(std::string_view host, std::string_view origin, bool loopback_only,
                    const std::vector<std::string>& names) {
  if (host.empty()) return false;
  const std::string_view name = HostName(host);
  if (loopback_only) {
    if (name != "127.0.0.1" && name != "localhost" && name != "[::1]") return false;
  } else if (!NamedHost(name, names)) {
    return false;
  }
  if (origin.empty()) return true;
  const size_t scheme = origin.find("://");
  if (scheme == std::string_view::npos) return false;
  const std::string_view kind = origin.substr(0, scheme);
  if (kind != "http" && kind != "https") return false;
  return origin.substr(scheme + 3) == host;
}

std::optional<CameraTarget> ParseCameraTarget(std::string_view target) {
  target = target.substr(0, target.find('?'));
  constexpr std::string_view kHead = "/camera/", kTail = ".jpg";
  if (target.size() <= kHead.size() + kTail.size() || target.substr(0, kHead.size()) != kHead ||
      target.substr(target.size() - kTail.size()) != kTail)
    return std::nullopt;
  const std::string_view ids = target.substr(kHead.size(), target.size() - kHead.size() - kTail.size());
  const size_t slash = ids.find('/');
  if (slash == std::string_view::npos) return std::nullopt;
  CameraTarget t{std::string(ids.substr(0, slash)), std::string(ids.substr(slash + 1))};
  if (!Token(t.robot) || !Token(t.camera)) return std::nullopt;
  return t;
}

bool RateLimit::Allow(std::chrono::steady_clock::time_point now) {
  if (now - window_start_ >= std::chrono::seconds(1)) {
    window_start_ = now;
    count_ = 0;
  }
  return ++count_ <= per_second_;
}

}  // namespace turf::viewer
