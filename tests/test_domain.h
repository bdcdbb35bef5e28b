// The DDS domain a test process uses. Fast DDS listens on 7400 + 250 * domain
// (+ small offsets): domains up to 99 keep those ports below Linux's ephemeral
// range (32768-60999), where another process's random socket could take a
// discovery port and silently break the test. Tests also use their own topic
// prefix, so two tests sharing a domain do not see each other's samples.
#pragma once

#include <unistd.h>

namespace turf::test {

inline int TestDomain(int salt = 0) { return 1 + static_cast<int>((getpid() + salt) % 99); }

}  // namespace turf::test
