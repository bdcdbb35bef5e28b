// A DDS participant for another vendor's topics (the Booster SDK's rt/low_state, rt/joint_ctrl): exact topic names
// (no turf prefix), the types' own registered names, and the QoS such SDKs use on the robot: best effort, volatile,
// keep last. turf's own topics go through dds::Participant (participant.h); this one exists so that robot programs
// written for a vendor SDK find the topics they expect. Transports as every turf participant (the profiles file's
// participant profile: UDP only); it announces its process as they do, and with security names a peer that never
// finishes authenticating (authentication_watch.h). Fast DDS stays in vendor_participant.cpp; the typed front-ends
// below only need the generated PubSubType.
//
// RAII: writers and readers delete their entities; the participant must outlive them. A reader's callback runs on a
// Fast DDS thread, one sample at a time, until the reader is destroyed.
#pragma once

#include <chrono>
#include <cstdint>
#include <functional>
#include <memory>
#include <string>

#include "dds/participant.h"  // Authentications (no Fast DDS in it)

namespace eprosima::fastdds::dds {
class TopicDataType;
}

namespace turf::dds {

struct VendorOptions {
  int domain = 0;
  std::string name = "turf";
  // DDS Security: an identity directory of `turf security init` (as ParticipantOptions::security); empty: off.
  std::string security;
  // For large samples (camera images, issue 16): the shared-memory transport besides UDPv4 (a local reader that
  // also has it gets an image without fragmenting it into datagrams), 4 MiB socket buffers, and writers that
  // publish asynchronously through a flow controller (kLargeSampleBytesPerMs): write() returns at once, Fast DDS's
  // own thread sends the datagrams paced, so a burst of fragments does not overflow a reader's socket buffer.
  bool large_samples = false;
  // With security: a participant that has not finished authenticating after this long is named in a warning, as
  // ParticipantOptions::authentication_timeout. 0: no watch.
  std::chrono::milliseconds authentication_timeout{20000};
};

// The flow controller's pace for large samples: at most this many bytes a millisecond (128 MB/s).
inline constexpr int kLargeSampleBytesPerMs = 128 * 1024;

class VendorParticipant {
 public:
  // Throws std::runtime_error if the participant cannot be created; std::invalid_argument for a security
  // directory that lacks a file or does not verify.
  VendorParticipant(int domain, const std::string& name);
  explicit VendorParticipant(const VendorOptions& options);
  ~VendorParticipant();
  VendorParticipant(const VendorParticipant&) = delete;
  VendorParticipant& operator=(const VendorParticipant&) = delete;

  int domain() const { return domain_; }
  // With security: as Participant::AuthenticationsNow (all zero without).
  Authentications AuthenticationsNow() const;

  class RawWriter;
  class RawReader;
  // Untyped: `type` is a new PubSubType (ownership passes); samples are of its type.
  std::unique_ptr<RawWriter> OpenWriter(const std::string& topic, eprosima::fastdds::dds::TopicDataType* type);
  // on_sample(sample, source timestamp in ns since the Unix epoch).
  std::unique_ptr<RawReader> OpenReader(const std::string& topic, eprosima::fastdds::dds::TopicDataType* type,
                                        std::function<void(const void*, int64_t)> on_sample);

  template <class PubSub>
  class Writer {
   public:
    explicit Writer(std::unique_ptr<RawWriter> raw) : raw_(std::move(raw)) {}
    bool Write(const typename PubSub::type& sample);
    // With an explicit source timestamp (ns since the Unix epoch), e.g. to test a receiver's staleness check.
    bool Write(const typename PubSub::type& sample, int64_t source_ns);
    int Matched() const;

   private:
    std::unique_ptr<RawWriter> raw_;
  };

  template <class PubSub>
  std::unique_ptr<Writer<PubSub>> MakeWriter(const std::string& topic) {
    return std::make_unique<Writer<PubSub>>(OpenWriter(topic, new PubSub()));
  }
  // The reader stays open as long as the returned handle lives.
  template <class PubSub>
  std::unique_ptr<RawReader> MakeReader(const std::string& topic,
                                        std::function<void(const typename PubSub::type&, int64_t)> on_sample) {
    return OpenReader(topic, new PubSub(), [f = std::move(on_sample)](const void* s, int64_t t) {
      f(*static_cast<const typename PubSub::type*>(s), t);
    });
  }

 private:
  struct Impl;
  int domain_;
  bool large_samples_ = false;
  std::unique_ptr<Impl> impl_;
};

// The untyped endpoints (defined in vendor_participant.cpp).
class VendorParticipant::RawWriter {
 public:
  virtual ~RawWriter() = default;
  virtual bool Write(const void* sample) = 0;
  virtual bool Write(const void* sample, int64_t source_ns) = 0;
  virtual int Matched() const = 0;
};
class VendorParticipant::RawReader {
 public:
  virtual ~RawReader() = default;
  virtual int Matched() const = 0;
};

template <class PubSub>
bool VendorParticipant::Writer<PubSub>::Write(const typename PubSub::type& sample) {
  return raw_->Write(&sample);
}
template <class PubSub>
bool VendorParticipant::Writer<PubSub>::Write(const typename PubSub::type& sample, int64_t source_ns) {
  return raw_->Write(&sample, source_ns);
}
template <class PubSub>
int VendorParticipant::Writer<PubSub>::Matched() const {
  return raw_->Matched();
}

}  // namespace turf::dds
