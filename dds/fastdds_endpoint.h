// What turf's two Fast DDS participants (participant.cpp: turf's topics; vendor_participant.cpp: another
// vendor's, e.g. the Booster SDK's) do alike with a Fast DDS endpoint. Internal to dds/.
#pragma once

#include <fastdds/dds/publisher/DataWriter.hpp>
#include <fastdds/dds/publisher/Publisher.hpp>
#include <fastdds/dds/subscriber/DataReader.hpp>

#include <cstdint>

namespace turf::dds {

// Readers matched to `writer` now.
inline int MatchedReaders(eprosima::fastdds::dds::DataWriter* writer) {
  eprosima::fastdds::dds::PublicationMatchedStatus status;
  writer->get_publication_matched_status(status);
  return status.current_count;
}

// Writers matched to `reader` now.
inline int MatchedWriters(eprosima::fastdds::dds::DataReader* reader) {
  eprosima::fastdds::dds::SubscriptionMatchedStatus status;
  reader->get_subscription_matched_status(status);
  return status.current_count;
}

// Deletes `writer` (made by `publisher`), emptying its history first. Fast DDS 2.9.1 (Debian 12) releases a deleted
// writer's samples without the writer's lock (RTPSWriter::deinit) while its event thread may be sending a periodic
// heartbeat: the heartbeat's scan for gaps in the history then meets released samples (sequence number 0) and never
// ends, holding the lock, and the deleting thread waits for it for good (eProsima/Fast-DDS#4076, fixed from 2.10;
// caught in a soak run, reproduced by tests/dds/writer_teardown_test.cpp). clear_history removes the samples under
// the lock, so deinit has none left to release. Readers lose nothing they would have kept: the writer is going.
inline void DeleteWriter(eprosima::fastdds::dds::Publisher* publisher, eprosima::fastdds::dds::DataWriter* writer) {
  writer->clear_history(nullptr);
  publisher->delete_datawriter(writer);
}

// Writes `sample` with the source timestamp `source_ns` (ns since the epoch of the writer's clock).
inline bool WriteStamped(eprosima::fastdds::dds::DataWriter* writer, const void* sample, int64_t source_ns) {
  const eprosima::fastrtps::Time_t t(static_cast<int32_t>(source_ns / 1'000'000'000),
                                     static_cast<uint32_t>(source_ns % 1'000'000'000));
  return writer->write_w_timestamp(const_cast<void*>(sample), eprosima::fastdds::dds::HANDLE_NIL, t) ==
         eprosima::fastrtps::types::ReturnCode_t::RETCODE_OK;
}

}  // namespace turf::dds
