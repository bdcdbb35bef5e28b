#include "participants/viewer/web_sessions.h"

#include <chrono>
#include <filesystem>
#include <fstream>
#include <sstream>

namespace turf::viewer::web {

namespace {

constexpr size_t kHeaderLimit = 8 * 1024;
constexpr size_t kBodyLimit = 4 * 1024;
constexpr size_t kMaxFile = 8 * 1024 * 1024;
constexpr size_t kMaxPageFrame = 64 * 1024;  // bigger WebSocket messages close the connection
// A request must arrive whole within this (also the next one on a kept-alive connection): a client that opens
// connections and sends nothing holds their slots no longer.
constexpr auto kHttpTimeout = std::chrono::seconds(10);
constexpr char kServer[] = "turf-viewer";
// The page needs nothing from elsewhere: scripts, styles and its WebSocket are
// all same-origin.
constexpr char kPolicy[] =
    "default-src 'self'; connect-src 'self'; img-src 'self' data:; frame-ancestors 'none'; base-uri 'none'";

std::string_view Std(beast::string_view s) { return {s.data(), s.size()}; }

// Request targets go into logs: short and printable.
std::string Clip(beast::string_view s) {
  std::string out;
  for (char c : s.substr(0, 64)) out += (c >= 0x20 && c < 0x7f) ? c : '?';
  return s.size() > 64 ? out + "..." : out;
}

http::response<http::string_body> Plain(http::status status, unsigned version, bool keep_alive, std::string body) {
  http::response<http::string_body> res{status, version};
  res.set(http::field::server, kServer);
  res.set(http::field::content_type, "text/plain; charset=utf-8");
  res.keep_alive(keep_alive);
  res.body() = std::move(body);
  res.prepare_payload();
  return res;
}

}  // namespace

// --- HttpSession ---

HttpSession::HttpSession(tcp::socket socket, std::shared_ptr<Shared> shared)
    : stream_(std::move(socket)), slot_(std::move(shared), RemoteAddress(stream_.socket())) {}

void HttpSession::Read() {
  parser_.emplace();
  parser_->header_limit(kHeaderLimit);
  parser_->body_limit(kBodyLimit);
  stream_.expires_after(kHttpTimeout);
  http::async_read(stream_, buffer_, *parser_,
                   [self = shared_from_this()](beast::error_code ec, size_t) { self->OnRead(ec); });
}

void HttpSession::OnRead(beast::error_code ec) {
  if (ec == http::error::end_of_stream) {
    stream_.socket().shutdown(tcp::socket::shutdown_send, ec);
    return;
  }
  if (ec) {
    // Malformed or oversized requests are refusals; timeouts and resets are not.
    if (ec.category() == http::make_error_code(http::error::bad_target).category())
      slot_.shared().Refuse(0, "http.malformed", ec.message());
    return;
  }
  http::request<http::string_body> request = parser_->release();
  ++slot_.shared().http_requests;
  if (websocket::is_upgrade(request)) {
    Upgrade(std::move(request));
    return;
  }
  Respond(StaticResponse(request));
}

void HttpSession::Upgrade(http::request<http::string_body> request) {
  Shared& shared = slot_.shared();
  if (request.target() != "/ws") {
    Respond(Plain(http::status::not_found, request.version(), false, "WebSocket path is /ws\n"));
    return;
  }
  if (!UpgradeAllowed(Std(request[http::field::host]), Std(request[http::field::origin]), shared.loopback_only,
                      shared.options.host_names)) {
    shared.Refuse(0, "http.origin",
                  "WebSocket from origin '" + Clip(request[http::field::origin]) + "' for host '" +
                      Clip(request[http::field::host]) + "'");
    Respond(Plain(http::status::forbidden, request.version(), false, "origin not allowed\n"));
    return;
  }
  std::make_shared<PageSession>(std::move(stream_), slot_.ptr())->Start(std::move(request));
}

http::response<http::string_body> HttpSession::DynamicResponse(const http::request<http::string_body>& request,
                                                               bool image) {
  const auto& handlers = slot_.shared().handlers;
  const std::optional<std::string> body = (image ? handlers.on_image : handlers.on_get)(Std(request.target()));
  if (!body) return Plain(http::status::not_found, request.version(), request.keep_alive(), "not found\n");
  http::response<http::string_body> res{http::status::ok, request.version()};
  res.set(http::field::server, kServer);
  res.set(http::field::content_type, image ? "image/jpeg" : "application/json");
  res.set(http::field::cache_control, "no-store");
  res.set("X-Content-Type-Options", "nosniff");
  res.set("Content-Security-Policy", kPolicy);
  res.keep_alive(request.keep_alive());
  if (request.method() == http::verb::head) {
    res.content_length(body->size());
  } else {
    res.body() = *body;
    res.prepare_payload();
  }
  return res;
}

http::response<http::string_body> HttpSession::StaticResponse(const http::request<http::string_body>& request) {
  const unsigned version = request.version();
  const bool keep_alive = request.keep_alive();
  if (request.method() != http::verb::get && request.method() != http::verb::head) {
    slot_.shared().Refuse(0, "http.method", "method " + Clip(request.method_string()));
    auto res = Plain(http::status::method_not_allowed, version, keep_alive, "GET or HEAD only\n");
    res.set(http::field::allow, "GET, HEAD");
    return res;
  }
  if (slot_.shared().handlers.on_get && Std(request.target()).rfind("/recording/", 0) == 0)
    return DynamicResponse(request, false);
  if (slot_.shared().handlers.on_image && Std(request.target()).rfind("/camera/", 0) == 0)
    return DynamicResponse(request, true);
  const std::optional<std::string> file = StaticFile(Std(request.target()));
  if (!file) {
    slot_.shared().Refuse(0, "http.bad_target", "target '" + Clip(request.target()) + "'");
    return Plain(http::status::not_found, version, keep_alive, "not found\n");
  }
  const std::filesystem::path path = std::filesystem::path(slot_.shared().options.web_root) / *file;
  std::error_code fs_error;
  const bool regular = std::filesystem::is_regular_file(path, fs_error);
  const uintmax_t size = regular ? std::filesystem::file_size(path, fs_error) : 0;
  std::ifstream in(path, std::ios::binary);
  if (!regular || fs_error || size > kMaxFile || !in)
    return Plain(http::status::not_found, version, keep_alive, "not found\n");
  std::ostringstream content;
  content << in.rdbuf();

  http::response<http::string_body> res{http::status::ok, version};
  res.set(http::field::server, kServer);
  res.set(http::field::content_type, ContentType(*file));
  res.set(http::field::cache_control, "no-cache");
  res.set("X-Content-Type-Options", "nosniff");
  res.set("Content-Security-Policy", kPolicy);
  res.keep_alive(keep_alive);
  if (request.method() == http::verb::head) {
    res.content_length(content.str().size());
  } else {
    res.body() = content.str();
    res.prepare_payload();
  }
  return res;
}

void HttpSession::Respond(http::response<http::string_body> response) {
  response_ = std::make_shared<http::response<http::string_body>>(std::move(response));
  http::async_write(stream_, *response_, [self = shared_from_this()](beast::error_code ec, size_t) {
    if (ec) return;
    if (self->response_->need_eof()) {
      self->stream_.socket().shutdown(tcp::socket::shutdown_send, ec);
      return;
    }
    self->response_.reset();
    self->Read();
  });
}

// --- PageSession ---

PageSession::PageSession(beast::tcp_stream stream, std::shared_ptr<Shared> shared)
    : ws_(std::move(stream)),
      slot_(std::move(shared), RemoteAddress(ws_.next_layer().socket())),
      id_(slot_.shared().next_client++),
      rate_(slot_.shared().options.max_messages_per_second) {}

PageSession::~PageSession() {
  if (!slot_.shared().pages.erase(id_)) return;
  --slot_.shared().page_count;
}

void PageSession::Start(http::request<http::string_body> request) {
  beast::get_lowest_layer(ws_).expires_never();  // the WebSocket's own timeouts from here on
  ws_.set_option(websocket::stream_base::timeout::suggested(beast::role_type::server));
  ws_.set_option(
      websocket::stream_base::decorator([](websocket::response_type& res) { res.set(http::field::server, kServer); }));
  ws_.read_message_max(kMaxPageFrame);
  ws_.async_accept(request, [self = shared_from_this()](beast::error_code ec) { self->OnAccept(ec); });
}

void PageSession::OnAccept(beast::error_code ec) {
  Shared& shared = slot_.shared();
  if (ec) {
    shared.Refuse(id_, "page.handshake", ec.message());
    return;
  }
  open_ = true;
  shared.pages[id_] = weak_from_this();
  ++shared.page_count;
  // A new page gets the greeting, then the newest field, statistics and state.
  Enqueue(Channel::kEvent, std::make_shared<const std::string>(shared.options.hello));
  const Channel kept[] = {Channel::kField, Channel::kStats, Channel::kState};
  for (const Channel c : kept)
    if (shared.latest[static_cast<int>(c)]) Enqueue(c, *shared.latest[static_cast<int>(c)]);
  Read();
}

void PageSession::Read() {
  ws_.async_read(buffer_, [self = shared_from_this()](beast::error_code ec, size_t) { self->OnRead(ec); });
}

void PageSession::OnRead(beast::error_code ec) {
  Shared& shared = slot_.shared();
  if (ec) {
    if (ec == websocket::error::message_too_big)
      shared.Refuse(id_, "page.too_large", "a message over 64 KiB: connection closed");
    open_ = false;
    return;
  }
  std::string text = beast::buffers_to_string(buffer_.data());
  buffer_.consume(buffer_.size());
  if (!ws_.got_text()) {
    shared.Refuse(id_, "page.binary", "binary messages are not understood");
  } else if (!rate_.Allow(std::chrono::steady_clock::now())) {
    shared.Refuse(id_, "page.rate_limited",
                  "more than " + std::to_string(shared.options.max_messages_per_second) + " messages a second");
  } else if (shared.handlers.on_message) {
    shared.handlers.on_message(id_, std::move(text));
  }
  Read();
}

void PageSession::Enqueue(Channel channel, const Message& message) {
  if (!open_) return;
  Shared& shared = slot_.shared();
  if (channel == Channel::kState) {
    if (state_) ++shared.frames_dropped;
    state_ = message;
  } else {
    if (queue_.size() >= shared.options.max_queued_events) {
      queue_.pop_front();
      ++shared.events_dropped;
    }
    queue_.push_back(message);
  }
  WriteNext();
}

void PageSession::WriteNext() {
  if (writing_ || !open_) return;
  if (!queue_.empty()) {
    in_flight_ = queue_.front();
    queue_.pop_front();
  } else if (state_) {
    in_flight_ = *state_;
    state_.reset();
  } else {
    return;
  }
  writing_ = true;
  ws_.text(true);
  ws_.async_write(asio::buffer(*in_flight_), [self = shared_from_this()](beast::error_code ec, size_t) {
    self->writing_ = false;
    self->in_flight_.reset();
    if (ec) {
      self->open_ = false;
      return;
    }
    ++self->slot_.shared().messages_sent;
    self->WriteNext();
  });
}

}  // namespace turf::viewer::web
