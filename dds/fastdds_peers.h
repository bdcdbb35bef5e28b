// What turf's two Fast DDS participants (participant.cpp: turf's topics; vendor_participant.cpp: another vendor's)
// do alike with other participants: say who they are in their discovery data, read who another one is, and under
// DDS Security tell an AuthenticationWatch of discoveries and authentications. Internal to dds/.
#pragma once

#include <fastdds/dds/domain/DomainParticipantListener.hpp>  // the discovery infos; HAVE_SECURITY
#include <fastdds/dds/domain/qos/DomainParticipantQos.hpp>

#include <string>

#include "dds/authentication_watch.h"
#include "dds/participant.h"

namespace turf::dds {

// Puts this process's host, pid, program and start time into `qos` as propagated properties, and returns them as
// a PeerInfo named `name` (its guid_prefix empty: the participant does not exist yet).
PeerInfo AnnounceSelf(const std::string& name, eprosima::fastdds::dds::DomainParticipantQos& qos);

// What a participant's discovery data says about it.
PeerInfo PeerOf(const eprosima::fastrtps::rtps::ParticipantProxyData& data);

// A GUID prefix as Fast DDS prints it.
std::string PrefixText(const eprosima::fastrtps::rtps::GuidPrefix_t& prefix);

// A participant discovered (its authentication starts) or gone.
void WatchDiscovery(AuthenticationWatch& watch, const eprosima::fastrtps::rtps::ParticipantDiscoveryInfo& info,
                    const PeerInfo& peer);

#if HAVE_SECURITY
// An authentication ended; a refused participant is named in a warning.
void WatchAuthentication(AuthenticationWatch& watch,
                         const eprosima::fastrtps::rtps::ParticipantAuthenticationInfo& info);
#endif

}  // namespace turf::dds
