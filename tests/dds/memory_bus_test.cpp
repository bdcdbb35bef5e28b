// dds::MemoryBus (dds/memory_bus.h): synchronous delivery of copies, Matched() at once, latched topics for late
// readers, bounded queues, and writers and readers on different threads. No DDS, no sleeps: a waiting test waits
// for a condition with a deadline.
#include <gtest/gtest.h>
#include <turf/idl/Clock.h>
#include <turf/idl/SimControl.h>
#include <turf/idl/SslRobot.h>
#include <turf/idl/SslVision.h>
#include <turf/idl/WorldState.h>

#include <atomic>
#include <chrono>
#include <condition_variable>
#include <memory>
#include <mutex>
#include <thread>
#include <vector>

#include "dds/memory_bus.h"

namespace turf {
namespace {

using namespace std::chrono_literals;

idl::Clock ClockAt(uint64_t frame) {
  idl::Clock c;
  c.frame(frame);
  c.sim_time_ns(static_cast<int64_t>(frame) * 2000000);
  return c;
}

TEST(MemoryBus, AWriteReachesEveryReaderOfItsTopicAtOnce) {
  dds::MemoryBus bus("test");
  int woken = 0;
  auto a = bus.MakeReader(dds::Topic::kClock, [&] { ++woken; });
  auto b = bus.MakeReader(dds::Topic::kClock);
  auto other = bus.MakeReader(dds::Topic::kWorldState);
  auto writer = bus.MakeWriter(dds::Topic::kClock);

  EXPECT_TRUE(writer->Write(ClockAt(7)));
  EXPECT_EQ(woken, 1);  // on the writer's thread, before Write returns
  std::vector<idl::Clock> got;
  ASSERT_TRUE(a->Take(&got));
  ASSERT_EQ(got.size(), 1u);
  EXPECT_EQ(got[0].frame(), 7u);
  ASSERT_TRUE(b->Take(&got));
  EXPECT_EQ(got[0].frame(), 7u);
  EXPECT_FALSE(a->Take(&got));  // taken once
  EXPECT_TRUE(got.empty());
  std::vector<idl::WorldState> states;
  EXPECT_FALSE(other->Take(&states));
}

TEST(MemoryBus, ReadersGetCopiesInWriteOrder) {
  dds::MemoryBus bus;
  auto reader = bus.MakeReader(dds::Topic::kControl);
  auto writer = bus.MakeWriter(dds::Topic::kControl);
  idl::SimControl request;
  request.client("me");
  for (uint64_t id = 1; id <= 3; ++id) {
    request.request_id(id);
    writer->Write(request);
  }
  request.client("changed after the write");
  std::vector<idl::SimControl> got;
  ASSERT_TRUE(reader->Take(&got));
  ASSERT_EQ(got.size(), 3u);
  for (uint64_t i = 0; i < 3; ++i) {
    EXPECT_EQ(got[i].request_id(), i + 1);
    EXPECT_EQ(got[i].client(), "me");
  }
}

TEST(MemoryBus, BusesAreApart) {
  dds::MemoryBus one;
  dds::MemoryBus two;
  auto reader = two.MakeReader(dds::Topic::kClock);
  auto writer = one.MakeWriter(dds::Topic::kClock);
  writer->Write(ClockAt(1));
  std::vector<idl::Clock> got;
  EXPECT_FALSE(reader->Take(&got));
  EXPECT_EQ(writer->Matched(), 0);
}

TEST(MemoryBus, MatchedCountsTheOtherSideOfTheTopic) {
  dds::MemoryBus bus;
  auto writer = bus.MakeWriter(dds::Topic::kSslCommandBlue);
  EXPECT_EQ(writer->Matched(), 0);
  auto r1 = bus.MakeReader(dds::Topic::kSslCommandBlue);
  auto yellow = bus.MakeReader(dds::Topic::kSslCommandYellow);  // same type, another topic
  EXPECT_EQ(writer->Matched(), 1);
  EXPECT_EQ(r1->Matched(), 1);
  EXPECT_EQ(yellow->Matched(), 0);
  {
    auto r2 = bus.MakeReader(dds::Topic::kSslCommandBlue);
    auto w2 = bus.MakeWriter(dds::Topic::kSslCommandBlue);
    EXPECT_EQ(writer->Matched(), 2);
    EXPECT_EQ(r1->Matched(), 2);
  }
  EXPECT_EQ(writer->Matched(), 1);
  EXPECT_EQ(r1->Matched(), 1);
  EXPECT_EQ(r1->DeadlinesMissed(), 0);
}

TEST(MemoryBus, ALatchedTopicGivesALateReaderEachWritersLastSample) {
  dds::MemoryBus bus;
  auto first = bus.MakeWriter(dds::Topic::kSslField);
  auto second = bus.MakeWriter(dds::Topic::kSslField);
  idl::SslField field;
  for (double length : {1.0, 2.0}) {
    field.field_length(length);
    first->Write(field);
  }
  field.field_length(9.0);
  second->Write(field);

  int woken = 0;
  auto late = bus.MakeReader(dds::Topic::kSslField, [&] { ++woken; });
  EXPECT_EQ(woken, 1);
  std::vector<idl::SslField> got;
  ASSERT_TRUE(late->Take(&got));
  ASSERT_EQ(got.size(), 2u);
  EXPECT_EQ(got[0].field_length(), 2.0);  // the first writer's last
  EXPECT_EQ(got[1].field_length(), 9.0);

  second.reset();  // a writer's sample goes with it
  auto later = bus.MakeReader(dds::Topic::kSslField);
  ASSERT_TRUE(later->Take(&got));
  ASSERT_EQ(got.size(), 1u);
  EXPECT_EQ(got[0].field_length(), 2.0);
}

TEST(MemoryBus, AnUnlatchedTopicGivesALateReaderNothing) {
  dds::MemoryBus bus;
  auto writer = bus.MakeWriter(dds::Topic::kClock);
  writer->Write(ClockAt(1));
  auto late = bus.MakeReader(dds::Topic::kClock);
  std::vector<idl::Clock> got;
  EXPECT_FALSE(late->Take(&got));
}

TEST(MemoryBus, AFullQueueCountsWhatItDrops) {
  using Reader = dds::Reader<idl::ClockPubSubType>;
  dds::MemoryBus bus;
  int woken = 0;
  auto reader = bus.MakeReader(dds::Topic::kClock, [&] { ++woken; });
  auto writer = bus.MakeWriter(dds::Topic::kClock);
  const size_t extra = 5;
  for (size_t i = 0; i < Reader::kMaxQueued + extra; ++i) writer->Write(ClockAt(i));
  EXPECT_EQ(reader->Overflowed(), extra);
  EXPECT_EQ(woken, static_cast<int>(Reader::kMaxQueued));  // a dropped sample wakes nobody
  std::vector<idl::Clock> got;
  ASSERT_TRUE(reader->Take(&got));
  ASSERT_EQ(got.size(), Reader::kMaxQueued);
  EXPECT_EQ(got.back().frame(), Reader::kMaxQueued - 1);  // the newest were dropped
  writer->Write(ClockAt(99));
  ASSERT_TRUE(reader->Take(&got));
  EXPECT_EQ(got.size(), 1u);
  EXPECT_EQ(reader->Overflowed(), extra);
}

// on_data runs outside the bus's lock: it may take and write, here a server answering on the writer's thread.
TEST(MemoryBus, OnDataMayWriteToTheBus) {
  dds::MemoryBus bus;
  auto replies = bus.MakeWriter(dds::Topic::kControlReply);
  std::unique_ptr<dds::Reader<idl::SimControlPubSubType>> requests;
  requests = bus.MakeReader(dds::Topic::kControl, [&] {
    std::vector<idl::SimControl> in;
    if (!requests || !requests->Take(&in)) return;
    for (const idl::SimControl& r : in) {
      idl::SimControlReply reply;
      reply.request_id(r.request_id());
      replies->Write(reply);
    }
  });
  auto answers = bus.MakeReader(dds::Topic::kControlReply);
  auto client = bus.MakeWriter(dds::Topic::kControl);
  idl::SimControl request;
  request.request_id(42);
  client->Write(request);
  std::vector<idl::SimControlReply> got;
  ASSERT_TRUE(answers->Take(&got));  // answered before Write returned
  ASSERT_EQ(got.size(), 1u);
  EXPECT_EQ(got[0].request_id(), 42u);
}

TEST(MemoryBus, EndpointsAreListedOnceFromTheTable) {
  dds::MemoryBus bus("pre");
  auto w1 = bus.MakeWriter(dds::Topic::kClock);
  auto w2 = bus.MakeWriter(dds::Topic::kClock);
  auto r = bus.MakeReader(dds::Topic::kControl);
  ASSERT_EQ(bus.Endpoints().size(), 2u);
  EXPECT_EQ(bus.TopicName(dds::Topic::kClock), "pre/clock");
  EXPECT_EQ(bus.TopicLines()[0], dds::EndpointLine("pre", dds::Topic::kClock, dds::Endpoint::kWriter));
}

// A writer thread and the reader's owner: every sample arrives once, in order, and on_data wakes the owner.
// Both wait on conditions with a deadline: the owner for data, the writer for room in the bounded queue.
TEST(MemoryBus, AWriterThreadAndAReaderThread) {
  constexpr uint64_t kCount = 20000;
  constexpr uint64_t kWindow = 1000;  // < Reader::kMaxQueued: the writer waits rather than overflow
  dds::MemoryBus bus;
  std::mutex mutex;
  std::condition_variable changed;
  bool pending = false;
  uint64_t taken = 0;
  auto reader = bus.MakeReader(dds::Topic::kClock, [&] {
    std::lock_guard<std::mutex> lock(mutex);
    pending = true;
    changed.notify_all();
  });
  auto writer = bus.MakeWriter(dds::Topic::kClock);
  const auto deadline = std::chrono::steady_clock::now() + 30s;
  std::thread producer([&] {
    for (uint64_t i = 0; i < kCount; ++i) {
      {
        std::unique_lock<std::mutex> lock(mutex);
        if (!changed.wait_until(lock, deadline, [&] { return i < taken + kWindow; })) return;
      }
      writer->Write(ClockAt(i));
    }
  });
  std::vector<idl::Clock> got;
  std::vector<uint64_t> frames;
  while (frames.size() < kCount && std::chrono::steady_clock::now() < deadline) {
    {
      std::unique_lock<std::mutex> lock(mutex);
      changed.wait_until(lock, deadline, [&] { return pending; });
      pending = false;
    }
    if (reader->Take(&got))
      for (const idl::Clock& c : got) frames.push_back(c.frame());
    std::lock_guard<std::mutex> lock(mutex);
    taken = frames.size();
    changed.notify_all();
  }
  producer.join();
  EXPECT_EQ(reader->Overflowed(), 0u);
  ASSERT_EQ(frames.size(), kCount);
  for (uint64_t i = 0; i < kCount; ++i) ASSERT_EQ(frames[i], i);
}

// Readers made and destroyed on one thread while another writes: no delivery reaches a reader that is gone.
TEST(MemoryBus, ReadersComeAndGoWhileAnotherThreadWrites) {
  dds::MemoryBus bus;
  auto writer = bus.MakeWriter(dds::Topic::kClock);
  std::atomic<bool> done{false};
  std::thread producer([&] {
    uint64_t i = 0;
    while (!done.load()) writer->Write(ClockAt(i++));
  });
  // Each round's notification count when its reader was destroyed: none may come after.
  std::vector<std::pair<std::shared_ptr<std::atomic<int>>, int>> gone;
  for (int round = 0; round < 500; ++round) {
    auto counter = std::make_shared<std::atomic<int>>(0);
    {
      auto reader = bus.MakeReader(dds::Topic::kClock, [counter] { counter->fetch_add(1); });
      std::vector<idl::Clock> got;
      reader->Take(&got);
    }
    gone.emplace_back(counter, counter->load());
  }
  done = true;
  producer.join();
  for (size_t i = 0; i < gone.size(); ++i)
    EXPECT_EQ(gone[i].first->load(), gone[i].second) << "round " << i << ": notified after its reader was destroyed";
}

}  // namespace
}  // namespace turf
