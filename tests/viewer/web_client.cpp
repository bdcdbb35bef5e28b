#include "tests/viewer/web_client.h"

#include <optional>

namespace turf::test {

namespace asio = boost::asio;
namespace beast = boost::beast;
namespace http = beast::http;
namespace websocket = beast::websocket;
using tcp = asio::ip::tcp;

namespace {
tcp::endpoint Loopback(int port) { return {asio::ip::make_address("127.0.0.1"), static_cast<uint16_t>(port)}; }
}  // namespace

HttpResult HttpRequest(http::verb method, int port, const std::string& target, const std::string& body,
                       const Headers& headers, std::chrono::milliseconds timeout) {
  asio::io_context ioc;
  beast::tcp_stream stream(ioc);
  http::request<http::string_body> req{method, target, 11};
  req.set(http::field::host, "127.0.0.1:" + std::to_string(port));
  for (const auto& [name, value] : headers) req.set(name, value);
  if (!body.empty()) req.set(http::field::content_type, "application/json");
  req.body() = body;
  req.prepare_payload();
  beast::flat_buffer buffer;
  http::response_parser<http::string_body> parser;
  parser.body_limit(64 * 1024 * 1024);
  HttpResult out;
  stream.expires_after(timeout);
  stream.async_connect(Loopback(port), [&](beast::error_code ec) {
    if (ec) {
      out.error = "connect: " + ec.message();
      return;
    }
    http::async_write(stream, req, [&](beast::error_code ec2, size_t) {
      if (ec2) {
        out.error = "write: " + ec2.message();
        return;
      }
      http::async_read(stream, buffer, parser, [&](beast::error_code ec3, size_t) {
        if (ec3) {
          out.error = "read: " + ec3.message();
          return;
        }
        out.status = static_cast<int>(parser.get().result_int());
        out.content_type = std::string(parser.get()[http::field::content_type]);
        out.body = parser.get().body();
      });
    });
  });
  ioc.run();
  return out;
}

int FreeTcpPort() {
  asio::io_context ioc;
  tcp::acceptor acceptor(ioc, Loopback(0));
  return acceptor.local_endpoint().port();
}

WsClient::WsClient() = default;
WsClient::~WsClient() {
  if (!open_) return;
  beast::error_code ec;
  beast::get_lowest_layer(*ws_).socket().close(ec);
}

bool WsClient::Connect(int port, const std::string& origin, std::string* error) {
  ws_ = std::make_unique<websocket::stream<beast::tcp_stream>>(ioc_);
  beast::error_code ec;
  beast::get_lowest_layer(*ws_).expires_after(std::chrono::seconds(5));
  ws_->set_option(websocket::stream_base::decorator([origin](websocket::request_type& req) {
    if (!origin.empty()) req.set(http::field::origin, origin);
  }));
  std::optional<beast::error_code> result;
  beast::get_lowest_layer(*ws_).async_connect(Loopback(port), [&](beast::error_code c) {
    if (c) {
      result = c;
      return;
    }
    ws_->async_handshake("127.0.0.1:" + std::to_string(port), "/ws", [&](beast::error_code h) { result = h; });
  });
  ioc_.restart();
  ioc_.run();
  beast::get_lowest_layer(*ws_).expires_never();
  if (!result || *result) {
    if (error) *error = result ? result->message() : "no answer";
    return false;
  }
  ws_->read_message_max(64 * 1024 * 1024);
  open_ = true;
  return true;
}

bool WsClient::Send(const std::string& text) { return Write(text, false); }

bool WsClient::SendBinary(const std::string& bytes) { return Write(bytes, true); }

bool WsClient::Write(const std::string& message, bool binary) {
  if (!open_) return false;
  beast::error_code ec;
  ws_->binary(binary);
  ws_->write(asio::buffer(message), ec);
  return !ec;
}

bool WsClient::ReadUntil(const std::function<bool(const std::string&)>& done, std::chrono::milliseconds timeout) {
  const auto deadline = std::chrono::steady_clock::now() + timeout;
  while (open_) {
    bool finished = false;
    beast::error_code result;
    ws_->async_read(buffer_, [&](beast::error_code ec, size_t) {
      finished = true;
      result = ec;
    });
    ioc_.restart();
    while (!finished && ioc_.run_one_until(deadline) > 0) {
    }
    if (!finished) {  // timed out: the stream is not usable after a cancelled read
      beast::error_code ec;
      beast::get_lowest_layer(*ws_).socket().cancel(ec);
      ioc_.restart();
      ioc_.run();
      open_ = false;
      return false;
    }
    if (result) {
      open_ = false;
      closed_ = true;
      return false;
    }
    const std::string text = beast::buffers_to_string(buffer_.data());
    buffer_.consume(buffer_.size());
    if (done(text)) return true;
  }
  return false;
}

}  // namespace turf::test
