#include "tests/viewer/webdriver.h"

#include <unistd.h>

#include <chrono>
#include <cstdlib>
#include <sstream>
#include <thread>

#include "tests/viewer/web_client.h"

namespace turf::test {

namespace http = boost::beast::http;
using nlohmann::json;

namespace {
constexpr char kElementKey[] = "element-6066-11e4-a52e-4f735466cecf";  // W3C web element identifier
}

std::string FindExecutable(const std::vector<std::string>& names) {
  std::vector<std::string> dirs = {"/usr/bin", "/usr/local/bin"};
  if (const char* path = std::getenv("PATH")) {
    std::stringstream s(path);
    for (std::string dir; std::getline(s, dir, ':');)
      if (!dir.empty()) dirs.push_back(dir);
  }
  for (const std::string& name : names)
    for (const std::string& dir : dirs)
      if (access((dir + "/" + name).c_str(), X_OK) == 0) return dir + "/" + name;
  return "";
}

WebDriver::~WebDriver() {
  if (!session_.empty()) Call("DELETE", "/session/" + session_);
}

std::optional<json> WebDriver::Call(const char* method, const std::string& path, const json& body) {
  const http::verb verb = std::string(method) == "GET"    ? http::verb::get
                          : std::string(method) == "POST" ? http::verb::post
                                                          : http::verb::delete_;
  const HttpResult r = HttpRequest(verb, port_, path, body.is_null() ? "" : body.dump(), {}, std::chrono::seconds(15));
  if (r.status == 0) {
    error_ = std::string(method) + " " + path + ": " + r.error;
    return std::nullopt;
  }
  json reply = json::parse(r.body, nullptr, false);
  if (reply.is_discarded() || !reply.contains("value")) {
    error_ = std::string(method) + " " + path + ": not a WebDriver answer: " + r.body.substr(0, 200);
    return std::nullopt;
  }
  if (r.status != 200) {
    error_ = std::string(method) + " " + path + ": " + reply["value"].dump().substr(0, 400);
    return std::nullopt;
  }
  return reply["value"];
}

bool WebDriver::WaitReady(int timeout_ms) {
  const auto end = std::chrono::steady_clock::now() + std::chrono::milliseconds(timeout_ms);
  while (std::chrono::steady_clock::now() < end) {
    const auto status = Call("GET", "/status");
    if (status && status->value("ready", false)) return true;
    std::this_thread::sleep_for(std::chrono::milliseconds(50));
  }
  return false;
}

bool WebDriver::NewSession(const std::string& chromium, const std::string& user_data_dir, int width, int height) {
  const json args = {"--headless",
                     "--no-sandbox",
                     "--disable-gpu",
                     "--disable-quic",
                     "--no-first-run",
                     "--disable-background-networking",
                     "--disable-component-update",
                     "--disable-sync",
                     "--disable-dev-shm-usage",
                     "--force-device-scale-factor=1",
                     "--window-size=" + std::to_string(width) + "," + std::to_string(height),
                     "--user-data-dir=" + user_data_dir};
  const json caps = {
      {"capabilities",
       {{"alwaysMatch", {{"browserName", "chrome"}, {"goog:chromeOptions", {{"binary", chromium}, {"args", args}}}}}}}};
  const auto value = Call("POST", "/session", caps);
  if (!value || !value->contains("sessionId")) return false;
  session_ = (*value)["sessionId"].get<std::string>();
  return true;
}

bool WebDriver::Navigate(const std::string& url) {
  return Call("POST", "/session/" + session_ + "/url", {{"url", url}}).has_value();
}

std::optional<json> WebDriver::Execute(const std::string& script, const json& args) {
  return Call("POST", "/session/" + session_ + "/execute/sync", {{"script", script}, {"args", args}});
}

std::optional<std::string> WebDriver::Find(const std::string& css) {
  const auto value = Call("POST", "/session/" + session_ + "/element", {{"using", "css selector"}, {"value", css}});
  if (!value || !value->contains(kElementKey)) return std::nullopt;
  return (*value)[kElementKey].get<std::string>();
}

bool WebDriver::Click(const std::string& element) {
  return Call("POST", "/session/" + session_ + "/element/" + element + "/click", json::object()).has_value();
}

std::optional<std::string> WebDriver::Text(const std::string& element) {
  const auto value = Call("GET", "/session/" + session_ + "/element/" + element + "/text");
  if (!value || !value->is_string()) return std::nullopt;
  return value->get<std::string>();
}

namespace {
json PointerActions(const json& moves) {
  return {{"actions",
           {{{"type", "pointer"}, {"id", "mouse"}, {"parameters", {{"pointerType", "mouse"}}}, {"actions", moves}}}}};
}
}  // namespace

bool WebDriver::Drag(int x0, int y0, int x1, int y1, int ms, int button) {
  const json moves = json::array({
      {{"type", "pointerMove"}, {"duration", 0}, {"origin", "viewport"}, {"x", x0}, {"y", y0}},
      {{"type", "pointerDown"}, {"button", button}},
      {{"type", "pause"}, {"duration", 50}},
      {{"type", "pointerMove"},
       {"duration", ms / 2},
       {"origin", "viewport"},
       {"x", (x0 + x1) / 2},
       {"y", (y0 + y1) / 2}},
      {{"type", "pointerMove"}, {"duration", ms / 2}, {"origin", "viewport"}, {"x", x1}, {"y", y1}},
      {{"type", "pause"}, {"duration", 50}},
      {{"type", "pointerUp"}, {"button", button}},
  });
  return Call("POST", "/session/" + session_ + "/actions", PointerActions(moves)).has_value();
}

std::optional<std::string> WebDriver::CurrentWindow() {
  const auto value = Call("GET", "/session/" + session_ + "/window");
  if (!value || !value->is_string()) return std::nullopt;
  return value->get<std::string>();
}

std::optional<std::string> WebDriver::NewWindow() {
  const auto value = Call("POST", "/session/" + session_ + "/window/new", {{"type", "window"}});
  if (!value || !value->contains("handle")) return std::nullopt;
  return (*value)["handle"].get<std::string>();
}

bool WebDriver::SwitchTo(const std::string& window) {
  return Call("POST", "/session/" + session_ + "/window", {{"handle", window}}).has_value();
}

std::optional<std::string> WebDriver::Screenshot() {
  const auto value = Call("GET", "/session/" + session_ + "/screenshot");
  if (!value || !value->is_string()) return std::nullopt;
  return Base64Decode(value->get<std::string>());
}

std::optional<std::string> Base64Decode(const std::string& text) {
  auto digit = [](char c) -> int {
    if (c >= 'A' && c <= 'Z') return c - 'A';
    if (c >= 'a' && c <= 'z') return c - 'a' + 26;
    if (c >= '0' && c <= '9') return c - '0' + 52;
    if (c == '+') return 62;
    if (c == '/') return 63;
    return -1;
  };
  std::string out;
  uint32_t bits = 0;
  int count = 0;
  for (char c : text) {
    if (c == '=' || c == '\n' || c == '\r') continue;
    const int d = digit(c);
    if (d < 0) return std::nullopt;
    bits = (bits << 6) | static_cast<uint32_t>(d);
    count += 6;
    if (count >= 8) {
      count -= 8;
      out += static_cast<char>((bits >> count) & 0xFF);
    }
  }
  return out;
}

}  // namespace turf::test
