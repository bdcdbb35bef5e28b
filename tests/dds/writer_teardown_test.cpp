// Deleting a reliable writer while Fast DDS sends its periodic heartbeats. Fast DDS 2.9.1 (Debian 12) releases a
// deleted writer's samples without the writer's lock while its event thread may be scanning the same history for
// a heartbeat's gaps; the scan then meets released samples and never ends (eProsima/Fast-DDS#4076, fixed from
// 2.10). A soak run caught a test hung so, closing a writer. turf empties the history under the lock
// first (dds/fastdds_endpoint.h: DeleteWriter). Without that, this test hung in each of 12 tries, after 4 to 881
// writers (it makes 3000); the test watchdog (tests/support/watchdog.cpp) then fails it with every thread's stack.
//
// Its own executable: Fast DDS keeps QoS profiles process-wide, and this one loads turf's with a 20 us heartbeat
// on the state profile, so that heartbeats run all the time and one meets a deletion.
#include <gtest/gtest.h>
#include <turf/idl/ClockPubSubTypes.h>
#include <unistd.h>

#include <chrono>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "dds/participant.h"
#include "tests/support/wake_wait.h"
#include "tests/test_domain.h"

namespace turf {
namespace {

// turf's QoS profiles with the state profile's writers sending a heartbeat every 20 us.
std::string FastHeartbeatQosFile() {
  std::ifstream in(TURF_SOURCE_DIR "/configs/qos/turf_qos.xml");
  std::stringstream text;
  text << in.rdbuf();
  std::string xml = text.str();
  const std::string profile = "<data_writer profile_name=\"turf.state\">";
  const size_t start = xml.find(profile);
  const size_t end = xml.find("</data_writer>", start);
  if (start == std::string::npos || end == std::string::npos) return "";
  xml.insert(end, "<times><heartbeatPeriod><sec>0</sec><nanosec>20000</nanosec></heartbeatPeriod></times>\n");
  const std::string path =
      (std::filesystem::temp_directory_path() / ("turf_fast_heartbeat_" + std::to_string(getpid()) + ".xml")).string();
  std::ofstream(path) << xml;
  return path;
}

TEST(WriterTeardown, AWriterDeletedWhileItsHeartbeatsRunIsDeleted) {
  const std::string qos_file = FastHeartbeatQosFile();
  ASSERT_FALSE(qos_file.empty()) << "no turf.state writer profile in configs/qos/turf_qos.xml";
  dds::ParticipantOptions options;
  options.domain = test::TestDomain();
  options.prefix = "teardown" + std::to_string(getpid());
  options.name = "teardown_writer";
  options.qos_file = qos_file;
  dds::Participant writing(options);
  options.name = "teardown_reader";
  dds::Participant reading(options);
  test::WakeWait wake;
  auto reader = reading.MakeReader(dds::Topic::kClock, [&wake] { wake.Wake(); });

  // Each writer writes 8 clocks (its whole history: held until the reader matches, then sent) and is deleted once
  // the reader has the last of them, with them all still in its history and its heartbeats running.
  constexpr int kWriters = 3000;
  constexpr int kSamples = 8;
  int64_t newest = -1;
  for (int w = 0; w < kWriters; ++w) {
    auto writer = writing.MakeWriter(dds::Topic::kClock);
    idl::Clock clock;
    for (int i = 0; i < kSamples; ++i) {
      clock.sim_time_ns(int64_t{w} * kSamples + i);
      ASSERT_TRUE(writer->Write(clock));
    }
    const int64_t last = clock.sim_time_ns();
    const bool got = wake.Until(std::chrono::steady_clock::now() + std::chrono::seconds(30), [&] {
      std::vector<idl::Clock> taken;
      if (reader->Take(&taken))
        for (const idl::Clock& c : taken) newest = std::max(newest, c.sim_time_ns());
      return newest >= last;
    });
    ASSERT_TRUE(got) << "writer " << w << ": the reader's newest clock is " << newest << ", not " << last;
  }
  std::filesystem::remove(qos_file);
}

}  // namespace
}  // namespace turf
