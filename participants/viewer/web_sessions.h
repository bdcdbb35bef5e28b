// The connections of web_server.cpp (internal): one HttpSession per TCP
// connection, which becomes a PageSession when the page opens its WebSocket.
// Everything here runs on the server's one I/O thread.
#pragma once

#include <boost/asio.hpp>
#include <boost/beast.hpp>

#include <atomic>
#include <cstdint>
#include <deque>
#include <map>
#include <memory>
#include <optional>
#include <string>

#include "core/pinned.h"
#include "participants/viewer/http_rules.h"
#include "participants/viewer/web_server.h"

namespace turf::viewer::web {

namespace asio = boost::asio;
namespace beast = boost::beast;
namespace http = beast::http;
namespace websocket = beast::websocket;
using tcp = asio::ip::tcp;
using Message = std::shared_ptr<const std::string>;

class PageSession;

// What the sessions share with the server; outlives every session.
struct Shared {
  WebServerOptions options;
  WebServerHandlers handlers;
  bool loopback_only = true;
  uint64_t next_client = 1;
  size_t connections = 0;
  std::map<asio::ip::address, size_t> by_address;  // open connections per remote address
  std::map<uint64_t, std::weak_ptr<PageSession>> pages;
  std::optional<Message> latest[3];  // kField, kStats, kState
  std::atomic<uint64_t> page_count{0}, http_requests{0}, messages_sent{0}, frames_dropped{0}, events_dropped{0};

  void Refuse(uint64_t client, const std::string& kind, const std::string& detail) {
    if (handlers.on_refused) handlers.on_refused(client, kind, detail);
  }
};

// The peer's address (unspecified if the socket has none any more).
inline asio::ip::address RemoteAddress(const tcp::socket& socket) {
  beast::error_code ec;
  const tcp::endpoint peer = socket.remote_endpoint(ec);
  return ec ? asio::ip::address() : peer.address();
}

// Counts an open connection, in all and from its address, for as long as it lives.
class ConnectionSlot : Pinned {
 public:
  ConnectionSlot(std::shared_ptr<Shared> shared, asio::ip::address from)
      : shared_(std::move(shared)), from_(std::move(from)) {
    ++shared_->connections;
    ++shared_->by_address[from_];
  }
  ~ConnectionSlot() {
    --shared_->connections;
    if (--shared_->by_address[from_] == 0) shared_->by_address.erase(from_);
  }
  Shared& shared() { return *shared_; }
  const std::shared_ptr<Shared>& ptr() const { return shared_; }

 private:
  std::shared_ptr<Shared> shared_;
  const asio::ip::address from_;
};

class HttpSession : public std::enable_shared_from_this<HttpSession> {
 public:
  HttpSession(tcp::socket socket, std::shared_ptr<Shared> shared);
  void Start() { Read(); }

 private:
  void Read();
  void OnRead(beast::error_code ec);
  void Upgrade(http::request<http::string_body> request);
  void Respond(http::response<http::string_body> response);
  http::response<http::string_body> StaticResponse(const http::request<http::string_body>& request);
  // A /recording/ target (JSON, on_get) or, with `image`, a /camera/ one (JPEG, on_image).
  http::response<http::string_body> DynamicResponse(const http::request<http::string_body>& request, bool image);

  beast::tcp_stream stream_;
  beast::flat_buffer buffer_;
  std::optional<http::request_parser<http::string_body>> parser_;
  std::shared_ptr<http::response<http::string_body>> response_;
  ConnectionSlot slot_;
};

class PageSession : public std::enable_shared_from_this<PageSession> {
 public:
  PageSession(beast::tcp_stream stream, std::shared_ptr<Shared> shared);
  ~PageSession();
  void Start(http::request<http::string_body> request);
  void Enqueue(Channel channel, const Message& message);
  uint64_t id() const { return id_; }

 private:
  void OnAccept(beast::error_code ec);
  void Read();
  void OnRead(beast::error_code ec);
  void WriteNext();

  websocket::stream<beast::tcp_stream> ws_;
  beast::flat_buffer buffer_;
  ConnectionSlot slot_;
  uint64_t id_;
  bool open_ = false;
  bool writing_ = false;
  std::optional<Message> state_;  // newest state not yet sent
  std::deque<Message> queue_;     // field, stats, events
  Message in_flight_;
  RateLimit rate_;
};

}  // namespace turf::viewer::web
