// A minimal W3C WebDriver client (the HTTP API chromedriver serves) for the
// viewer's browser test: a session, navigation, scripts, clicks, pointer drags
// and screenshots. Every call returns a value or nullopt/false, never throws.
#pragma once

#include <nlohmann/json.hpp>

#include <optional>
#include <string>
#include <vector>

namespace turf::test {

// The first of `names` found as an executable in /usr/bin, /usr/local/bin or
// $PATH; empty if none.
std::string FindExecutable(const std::vector<std::string>& names);

class WebDriver {
 public:
  explicit WebDriver(int port) : port_(port) {}
  ~WebDriver();
  WebDriver(const WebDriver&) = delete;
  WebDriver& operator=(const WebDriver&) = delete;

  // Waits for chromedriver to answer /status with ready.
  bool WaitReady(int timeout_ms);
  // Starts headless Chromium with the test's flags and a fresh profile.
  bool NewSession(const std::string& chromium, const std::string& user_data_dir, int width, int height);
  bool Navigate(const std::string& url);
  // Runs `script` (a function body: use `return`, `arguments[i]`) in the page.
  std::optional<nlohmann::json> Execute(const std::string& script,
                                        const nlohmann::json& args = nlohmann::json::array());
  std::optional<std::string> Find(const std::string& css);  // element id
  bool Click(const std::string& element);
  std::optional<std::string> Text(const std::string& element);
  // Presses `button` (0 left, 2 right) at (x0, y0), moves to (x1, y1) over
  // `ms` and releases (viewport CSS pixels).
  bool Drag(int x0, int y0, int x1, int y1, int ms, int button = 0);
  // Opens a new window (a second page) and returns its handle; SwitchTo makes
  // a window the one the other calls act on.
  std::optional<std::string> CurrentWindow();
  std::optional<std::string> NewWindow();
  bool SwitchTo(const std::string& window);
  // The page as PNG bytes.
  std::optional<std::string> Screenshot();
  const std::string& error() const { return error_; }

 private:
  std::optional<nlohmann::json> Call(const char* method, const std::string& path,
                                     const nlohmann::json& body = nlohmann::json());
  int port_;
  std::string session_;
  std::string error_;
};

std::optional<std::string> Base64Decode(const std::string& text);

}  // namespace turf::test
