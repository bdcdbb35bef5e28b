// turf-viewer's node in-process on a thread of its own, on the test's DDS domain and prefix, serving the page's
// files from the source tree on a port the kernel picked.
#pragma once

#include <memory>
#include <string>

#include "participants/viewer/viewer_node.h"
#include "tests/support/in_process.h"

namespace turf::test {

class ViewerUnderTest : public OnThread<ViewerNode> {
 public:
  explicit ViewerUnderTest(const dds::ParticipantOptions& dds) : OnThread(std::make_unique<ViewerNode>(Options(dds))) {}
  int port() { return node().port(); }
  std::string origin() { return "http://127.0.0.1:" + std::to_string(port()); }

 private:
  static ViewerOptions Options(const dds::ParticipantOptions& dds) {
    auto o = OnDds<ViewerOptions>(dds);
    o.port = 0;
    o.web_root = TURF_SOURCE_DIR "/participants/viewer/web";
    return o;
  }
};

}  // namespace turf::test
