// turf-viewer's HTTP and WebSocket server: serves the page's static files and
// streams JSON messages to every open page. It knows nothing of DDS or of what
// the messages mean (see viewer_model.h).
//
// Library: Boost.Beast over Boost.Asio (Debian's libboost-dev, 1.74). Of the
// Debian 12 candidates it is the best kept (Boost's release cycle, used widely,
// header-only here, no extra runtime library), and it has HTTP and WebSocket in
// one library; civetweb (C, 1.15) is a whole embedded server with its own
// threads and config, and websocketpp 0.8 has seen no upstream release since
// 2020.
//
// Threads: one I/O thread owns every socket. Publish() and SendTo() may be
// called from any thread; they post to the I/O thread and never block.
// Per page: the newest state message waits in a single slot (an older one not
// yet sent is dropped: a slow page skips frames, it never stalls anyone), and
// other messages in a bounded queue (oldest dropped when full).
// Limits: GET/HEAD only, headers <= 8 KiB, one WebSocket path (/ws), at most
// `max_clients` open connections and `max_clients_per_address` from one address (one client cannot take them
// all; a connection sending no request for 10 s is closed), page messages <= 64 KiB (bigger: the
// connection is closed) and `max_messages_per_second` (more: refused).
#pragma once

#include <cstdint>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "core/pinned.h"

namespace turf::viewer {

// What a message is for: the newest of kField, kStats and kState is kept and
// sent to a page when it connects; kEvent messages go out once.
enum class Channel { kField, kStats, kState, kEvent };

struct WebServerOptions {
  std::string listen = "127.0.0.1";  // IPv4 or IPv6 address to bind
  uint16_t port = 8080;              // 0: any free port (see WebServer::port())
  std::string web_root;              // directory of index.html, app.js, style.css
  std::string hello;                 // the first message every page gets
  size_t max_clients = 64;           // a browser keeps up to 6 connections a page
  size_t max_clients_per_address = 24;
  int max_messages_per_second = 200;
  size_t max_queued_events = 64;  // per page
  // On a non-loopback binding: the names a page may reach the server by besides IP addresses and localhost
  // (http_rules.h's DNS-rebinding guard; PageHostNames).
  std::vector<std::string> host_names;
};

struct WebServerHandlers {
  // A text message from page `client` (on the I/O thread: hand it off fast).
  std::function<void(uint64_t client, std::string text)> on_message;
  // Input refused by the server itself, e.g. "page.binary", "http.bad_target".
  std::function<void(uint64_t client, const std::string& kind, const std::string& detail)> on_refused;
  // A GET or HEAD of a target under /recording/ (query included), answered with this JSON, or 404 when it
  // gives nullopt (on the I/O thread: it must be quick and thread-safe). Unset: those targets are files too.
  std::function<std::optional<std::string>(std::string_view target)> on_get;
  // The same for targets under /camera/, answered as image/jpeg (the camera panel; camera_frames.h).
  std::function<std::optional<std::string>(std::string_view target)> on_image;
};

struct WebServerStats {
  uint64_t pages = 0;           // open WebSocket connections
  uint64_t http_requests = 0;   // served, all kinds
  uint64_t messages_sent = 0;   // to pages
  uint64_t frames_dropped = 0;  // state messages a slow page skipped
  uint64_t events_dropped = 0;  // queued messages dropped for a slow page
};

class WebServer : Pinned {
 public:
  // Binds and starts the I/O thread; nullptr (and `error` says why) if the
  // address is not an IP address or cannot be bound.
  static std::unique_ptr<WebServer> Start(WebServerOptions options, WebServerHandlers handlers, std::string* error);
  ~WebServer();

  uint16_t port() const;
  std::string Url() const;  // http://<listen>:<port>/
  void Publish(Channel channel, std::string message);
  void SendTo(uint64_t client, std::string message);
  WebServerStats Stats() const;

 private:
  class Impl;
  explicit WebServer(std::unique_ptr<Impl> impl);
  std::unique_ptr<Impl> impl_;
};

}  // namespace turf::viewer
