#include "participants/viewer/web_server.h"

#include <chrono>
#include <thread>

#include "participants/viewer/web_sessions.h"

namespace turf::viewer {

using namespace web;

namespace {
// Broadcasts waiting for the I/O thread past which state frames are skipped,
// so a stalled I/O thread cannot make the DDS side queue without bound.
constexpr int kMaxPosted = 32;
}  // namespace

class WebServer::Impl {
 public:
  Impl(std::shared_ptr<Shared> shared, const tcp::endpoint& endpoint, std::string* error)
      : shared_(std::move(shared)), acceptor_(ioc_), retry_(ioc_) {
    beast::error_code ec;
    acceptor_.open(endpoint.protocol(), ec);
    if (!ec) acceptor_.set_option(asio::socket_base::reuse_address(true), ec);
    if (!ec) acceptor_.bind(endpoint, ec);
    if (!ec) acceptor_.listen(asio::socket_base::max_listen_connections, ec);
    if (ec) {
      *error = "cannot listen on " + endpoint.address().to_string() + ":" + std::to_string(endpoint.port()) + ": " +
               ec.message();
      return;
    }
    port_ = acceptor_.local_endpoint().port();
    address_ = endpoint.address();
    Accept();
    thread_ = std::thread([this] { ioc_.run(); });
  }
  ~Impl() {
    ioc_.stop();
    if (thread_.joinable()) thread_.join();
  }

  bool listening() const { return port_ != 0; }
  uint16_t port() const { return port_; }
  std::string Url() const {
    const std::string host = address_.is_v6() ? "[" + address_.to_string() + "]" : address_.to_string();
    return "http://" + host + ":" + std::to_string(port_) + "/";
  }

  void Publish(Channel channel, std::string message) {
    if (channel == Channel::kState && posted_.load() >= kMaxPosted) {
      ++shared_->frames_dropped;
      return;
    }
    auto m = std::make_shared<const std::string>(std::move(message));
    ++posted_;
    asio::post(ioc_, [this, channel, m] {
      --posted_;
      if (channel != Channel::kEvent) shared_->latest[static_cast<int>(channel)] = m;
      for (auto& [id, weak] : shared_->pages)
        if (auto page = weak.lock()) page->Enqueue(channel, m);
    });
  }

  void SendTo(uint64_t client, std::string message) {
    auto m = std::make_shared<const std::string>(std::move(message));
    asio::post(ioc_, [this, client, m] {
      const auto it = shared_->pages.find(client);
      if (it == shared_->pages.end()) return;
      if (auto page = it->second.lock()) page->Enqueue(Channel::kEvent, m);
    });
  }

  WebServerStats Stats() const {
    const Shared& s = *shared_;
    return {s.page_count.load(), s.http_requests.load(), s.messages_sent.load(), s.frames_dropped.load(),
            s.events_dropped.load()};
  }

 private:
  void Accept() {
    acceptor_.async_accept(ioc_, [this](beast::error_code ec, tcp::socket socket) {
      if (ec == asio::error::operation_aborted) return;
      if (ec) {  // e.g. out of file descriptors: try again a little later
        retry_.expires_after(std::chrono::milliseconds(100));
        retry_.async_wait([this](beast::error_code) { Accept(); });
        return;
      }
      const asio::ip::address from = web::RemoteAddress(socket);
      const auto open_from = shared_->by_address.find(from);
      if (shared_->connections >= shared_->options.max_clients) {
        shared_->Refuse(0, "http.too_many_clients",
                        std::to_string(shared_->options.max_clients) + " connections are open already");
        socket.close(ec);
      } else if (open_from != shared_->by_address.end() &&
                 open_from->second >= shared_->options.max_clients_per_address) {
        shared_->Refuse(0, "http.too_many_from_address",
                        std::to_string(open_from->second) + " connections from " + from.to_string() + " are open");
        socket.close(ec);
      } else {
        std::make_shared<HttpSession>(std::move(socket), shared_)->Start();
      }
      Accept();
    });
  }

  std::shared_ptr<Shared> shared_;
  asio::io_context ioc_{1};
  tcp::acceptor acceptor_;
  asio::steady_timer retry_;
  asio::ip::address address_;
  uint16_t port_ = 0;
  std::atomic<int> posted_{0};
  std::thread thread_;
};

std::unique_ptr<WebServer> WebServer::Start(WebServerOptions options, WebServerHandlers handlers, std::string* error) {
  beast::error_code ec;
  const asio::ip::address address = asio::ip::make_address(options.listen, ec);
  if (ec) {
    *error = "--listen: not an IP address: '" + options.listen + "'";
    return nullptr;
  }
  auto shared = std::make_shared<Shared>();
  shared->options = std::move(options);
  shared->handlers = std::move(handlers);
  shared->loopback_only = address.is_loopback();
  const tcp::endpoint endpoint(address, shared->options.port);
  auto impl = std::make_unique<Impl>(std::move(shared), endpoint, error);
  if (!impl->listening()) return nullptr;
  return std::unique_ptr<WebServer>(new WebServer(std::move(impl)));
}

WebServer::WebServer(std::unique_ptr<Impl> impl) : impl_(std::move(impl)) {}
WebServer::~WebServer() = default;
uint16_t WebServer::port() const { return impl_->port(); }
std::string WebServer::Url() const { return impl_->Url(); }
void WebServer::Publish(Channel channel, std::string message) { impl_->Publish(channel, std::move(message)); }
void WebServer::SendTo(uint64_t client, std::string message) { impl_->SendTo(client, std::move(message)); }
WebServerStats WebServer::Stats() const { return impl_->Stats(); }

}  // namespace turf::viewer
