// A small HTTP and WebSocket client for tests (Boost.Beast), every call
// bounded by a timeout so a broken server fails a test instead of hanging it.
#pragma once

#include <boost/asio.hpp>
#include <boost/beast.hpp>

#include <chrono>
#include <functional>
#include <memory>
#include <string>
#include <utility>
#include <vector>

namespace turf::test {

struct HttpResult {
  int status = 0;  // 0: no response (see error)
  std::string body;
  std::string content_type;
  std::string error;
};

using Headers = std::vector<std::pair<std::string, std::string>>;

HttpResult HttpRequest(boost::beast::http::verb method, int port, const std::string& target,
                       const std::string& body = "", const Headers& headers = {},
                       std::chrono::milliseconds timeout = std::chrono::seconds(5));
inline HttpResult HttpGet(int port, const std::string& target, const Headers& headers = {}) {
  return HttpRequest(boost::beast::http::verb::get, port, target, "", headers);
}

// A TCP port that was free a moment ago on 127.0.0.1.
int FreeTcpPort();

class WsClient {
 public:
  WsClient();
  ~WsClient();
  // Opens ws://127.0.0.1:<port>/ws; `origin` empty sends no Origin header.
  bool Connect(int port, const std::string& origin, std::string* error);
  bool Send(const std::string& text);
  bool SendBinary(const std::string& bytes);
  // Reads messages, handing each to `done`, until it answers true (then true),
  // or the timeout or a closed connection (then false).
  bool ReadUntil(const std::function<bool(const std::string&)>& done,
                 std::chrono::milliseconds timeout = std::chrono::seconds(5));
  bool open() const { return open_; }
  // The connection ended by the peer or an error, not by a ReadUntil timeout.
  bool closed() const { return closed_; }

 private:
  bool Write(const std::string& message, bool binary);  // one text or binary frame
  boost::asio::io_context ioc_;
  std::unique_ptr<boost::beast::websocket::stream<boost::beast::tcp_stream>> ws_;
  boost::beast::flat_buffer buffer_;
  bool open_ = false;
  bool closed_ = false;
};

}  // namespace turf::test
