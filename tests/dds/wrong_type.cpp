// Built as is: the right types compile. Built with TURF_WRONG_TYPE=1, 2, 3 by the ctests dds_wrong_type_writer,
// dds_wrong_type_reader and dds_wrong_type_forged (tests/dds/CMakeLists.txt), which expect the error named there.
#include <turf/idl/SslRobotPubSubTypes.h>
#include <turf/idl/WorldStatePubSubTypes.h>

#include "dds/participant.h"

namespace turf::test {

void UseTopics(dds::Participant& participant) {
#if TURF_WRONG_TYPE == 1
  // A writer of commands on the world-state topic.
  auto writer = participant.MakeWriter<idl::SslRobotCommandPubSubType>(dds::Topic::kWorldState);
  (void)writer;
#elif TURF_WRONG_TYPE == 2
  // A reader of world states on the blue command topic.
  auto reader = participant.MakeReader<idl::WorldStatePubSubType>(dds::Topic::kSslCommandBlue);
  (void)reader;
#elif TURF_WRONG_TYPE == 3
  // A topic paired with another type by hand.
  const dds::TopicDef<idl::SslRobotCommandPubSubType> forged(dds::TopicId::kWorldState);
  auto writer = participant.MakeWriter(forged);
  (void)writer;
#else
  auto writer = participant.MakeWriter<idl::WorldStatePubSubType>(dds::Topic::kWorldState);
  auto reader = participant.MakeReader<idl::SslRobotCommandPubSubType>(dds::Topic::kSslCommandBlue);
  const dds::TopicDef<idl::SslRobotCommandPubSubType> copied = dds::Topic::kSslCommandYellow;
  auto deduced = participant.MakeReader(copied, [] {});
  (void)writer;
  (void)reader;
  (void)deduced;
#endif
}

}  // namespace turf::test
