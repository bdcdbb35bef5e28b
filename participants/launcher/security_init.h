// `turf security init DIR`: the files DDS Security needs (issue 19), made with openssl from Debian:
//
//   DIR/ca.key, DIR/ca.pem         the match's certificate authority (keep ca.key on the operator's machine)
//   DIR/governance.xml, .p7s       the domain's rules (dds/security_policy.h), signed by the CA
//   DIR/<identity>/                one per identity (dds::IdentityNames(): sim, the bridges, blue, yellow,
//                                  operator, observer), all a participant needs: `--security DIR/<identity>`
//       key.pem, cert.pem          its private key and its certificate, signed by the CA
//       ca.pem, governance.p7s     copies of the CA certificate and the signed governance
//       permissions.xml, .p7s      what it may publish and subscribe, signed by the CA
//
// Give a team's machine only its own identity directory. Keys are ECDSA P-256; private keys are mode 0600.
#pragma once

#include <string>
#include <vector>

#include "dds/security_policy.h"

namespace turf::launch {

struct SecurityInitOptions {
  std::string dir;
  std::string prefix = "turf";  // the topics' prefix the permissions name
  dds::SecurityProfile profile = dds::SecurityProfile::kLab;
  dds::Protection protection = dds::Protection::kEncrypt;
  int days = 365;  // certificates and permissions are valid from yesterday for this many days
};

// Makes every file; an error message per failure (empty: done). Refuses a DIR that already has a ca.pem.
std::vector<std::string> InitSecurity(const SecurityInitOptions& options);

}  // namespace turf::launch
