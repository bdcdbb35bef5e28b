#include "codecs/simspark/framing.h"

#include <gtest/gtest.h>

#include <string>

namespace turf::simspark {
namespace {

using namespace std::string_literals;

void FeedString(FrameDecoder* d, const std::string& bytes) { d->Feed(bytes.data(), bytes.size()); }

TEST(Framing, FramePrefixesTheBigEndianLength) {
  EXPECT_EQ(Frame("(syn)"), "\x00\x00\x00\x05(syn)"s);
  EXPECT_EQ(Frame(""), "\x00\x00\x00\x00"s);
  const std::string big(0x010203, 'x');
  const std::string framed = Frame(big);
  ASSERT_EQ(framed.size(), 4u + 0x010203);
  EXPECT_EQ(framed.substr(0, 4), "\x00\x01\x02\x03"s);
  EXPECT_EQ(framed.substr(4), big);
}

TEST(Framing, DecodesByteByByte) {
  const std::string stream = "\x00\x00\x00\x05(syn)"s + "\x00\x00\x00\x0a(he1 0.50)"s;
  FrameDecoder d;
  std::vector<std::string> got;
  for (size_t i = 0; i < stream.size(); ++i) {
    d.Feed(&stream[i], 1);
    while (auto payload = d.Next()) got.push_back(*payload);
    EXPECT_EQ(d.error(), FrameError::kOk);
    if (i == 2) {
      EXPECT_EQ(d.buffered(), 3u);
    }
    if (i == 5) {
      EXPECT_EQ(d.buffered(), 6u);
    }
  }
  ASSERT_EQ(got.size(), 2u);
  EXPECT_EQ(got[0], "(syn)");
  EXPECT_EQ(got[1], "(he1 0.50)");
  EXPECT_EQ(d.buffered(), 0u);
}

TEST(Framing, TwoFramesAndAPartOneInOneFeed) {
  FrameDecoder d;
  FeedString(&d,
             "\x00\x00\x00\x01"
             "a"
             "\x00\x00\x00\x02"
             "bc"
             "\x00\x00\x00\x03"
             "d"s);
  EXPECT_EQ(d.Next(), "a");
  EXPECT_EQ(d.Next(), "bc");
  EXPECT_EQ(d.Next(), std::nullopt);
  EXPECT_EQ(d.buffered(), 5u);
  FeedString(&d, "ef");
  EXPECT_EQ(d.Next(), "def");
  EXPECT_EQ(d.Next(), std::nullopt);
  EXPECT_EQ(d.buffered(), 0u);
}

TEST(Framing, ZeroLengthFramesAreSkipped) {
  FrameDecoder d;
  FeedString(&d, "\x00\x00\x00\x00\x00\x00\x00\x00\x00\x00\x00\x01x\x00\x00\x00\x00"s);
  EXPECT_EQ(d.Next(), "x");
  EXPECT_EQ(d.Next(), std::nullopt);
  EXPECT_EQ(d.error(), FrameError::kOk);
  EXPECT_EQ(d.buffered(), 0u);
}

TEST(Framing, HugePrefixIsAnErrorAtOnce) {
  FrameDecoder d;
  FeedString(&d, "\xff\xff\xff"s);
  EXPECT_EQ(d.error(), FrameError::kOk);  // not yet a whole prefix
  FeedString(&d, "\xff"s);
  EXPECT_EQ(d.error(), FrameError::kTooLarge);  // without waiting for 4 GB
  EXPECT_EQ(d.buffered(), 0u);
  FeedString(&d, "\x00\x00\x00\x01x"s);  // nothing after an error
  EXPECT_EQ(d.Next(), std::nullopt);
  EXPECT_EQ(d.buffered(), 0u);
  EXPECT_EQ(d.error(), FrameError::kTooLarge);
}

TEST(Framing, MaxPayloadIsInclusive) {
  FrameDecoder d(8);
  FeedString(&d, Frame("12345678"));
  EXPECT_EQ(d.Next(), "12345678");
  FeedString(&d, "\x00\x00\x00\x09"s);
  EXPECT_EQ(d.error(), FrameError::kTooLarge);

  FrameDecoder agent;  // default: 64 KiB
  FeedString(&agent, "\x00\x01\x00\x00"s);
  EXPECT_EQ(agent.error(), FrameError::kOk);
  FeedString(&agent, "\x00\x01\x00\x01"s);  // inside the first frame's payload: still fine
  EXPECT_EQ(agent.error(), FrameError::kOk);
  FrameDecoder agent2;
  FeedString(&agent2, "\x00\x01\x00\x01"s);
  EXPECT_EQ(agent2.error(), FrameError::kTooLarge);
}

TEST(Framing, FramesBeforeABadPrefixAreStillDelivered) {
  FrameDecoder d;
  FeedString(&d, Frame("(syn)") + "\x7f\x00\x00\x00"s + "junk");
  EXPECT_EQ(d.error(), FrameError::kTooLarge);
  EXPECT_EQ(d.Next(), "(syn)");
  EXPECT_EQ(d.Next(), std::nullopt);
}

TEST(Framing, RoundTripsBinaryPayloads) {
  std::string payload;
  for (int i = 0; i < 256; ++i) payload.push_back(static_cast<char>(i));
  FrameDecoder d;
  FeedString(&d, Frame(payload) + Frame(payload));
  EXPECT_EQ(d.Next(), payload);
  EXPECT_EQ(d.Next(), payload);
}

}  // namespace
}  // namespace turf::simspark
