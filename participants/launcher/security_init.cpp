#include "participants/launcher/security_init.h"

#include <fmt/format.h>
#include <sys/stat.h>

#include <chrono>
#include <ctime>
#include <filesystem>
#include <fstream>

#include "participants/launcher/run_program.h"

namespace turf::launch {

namespace fs = std::filesystem;

namespace {

constexpr const char* kCurve = "ec_paramgen_curve:prime256v1";

// "2026-11-24T00:00:00", `days` from today (UTC).
std::string DayFromToday(int days) {
  const std::time_t t = std::chrono::system_clock::to_time_t(std::chrono::system_clock::now()) + days * 86400L;
  std::tm tm{};
  gmtime_r(&t, &tm);
  char buffer[32];
  std::strftime(buffer, sizeof(buffer), "%Y-%m-%dT00:00:00", &tm);
  return buffer;
}

// An openssl subject for the certificate whose permissions name SubjectOf(identity) ("CN=turf blue,O=turf").
std::string OpensslSubject(const std::string& common_name) { return "/O=turf/CN=" + common_name; }

class Maker {
 public:
  explicit Maker(const SecurityInitOptions& o) : o_(o), dir_(o.dir) {}

  std::vector<std::string> Run() {
    if (fs::exists(dir_ / "ca.pem"))
      return {dir_.string() + " already has a ca.pem: remove the directory to make a new CA and identities"};
    std::error_code ec;
    fs::create_directories(dir_, ec);
    if (ec) return {fmt::format("cannot create {}: {}", dir_.string(), ec.message())};
    if (!MakeCa() || !Signed(dir_ / "governance.xml", dds::GovernanceXml(o_.protection))) return errors_;
    for (const std::string& identity : dds::IdentityNames())
      if (!MakeIdentity(identity)) break;
    return errors_;
  }

 private:
  bool Openssl(std::vector<std::string> args) {
    args.insert(args.begin(), "openssl");
    const ProgramResult r = RunProgram(args);
    if (r.exit_status == 0) return true;
    if (r.exit_status < 0 && r.output.empty())
      errors_.push_back("cannot run openssl (Debian package openssl; scripts/setup.sh installs it)");
    else
      errors_.push_back(fmt::format("openssl {} failed (exit status {}): {}", args[1], r.exit_status, r.output));
    return false;
  }
  bool Write(const fs::path& path, const std::string& text) {
    std::ofstream out(path, std::ios::trunc);
    out << text;
    if (out.good()) return true;
    errors_.push_back("cannot write " + path.string());
    return false;
  }
  bool Private(const fs::path& key) {
    if (chmod(key.c_str(), 0600) == 0) return true;
    errors_.push_back("cannot make " + key.string() + " private (chmod 0600)");
    return false;
  }
  // Writes `xml` and its S/MIME signature by the CA next to it (<name>.p7s), as DDS Security reads them.
  bool Signed(const fs::path& xml_path, const std::string& xml) {
    fs::path p7s = xml_path;
    p7s.replace_extension(".p7s");
    return Write(xml_path, xml) && Openssl({"smime", "-sign", "-in", xml_path, "-text", "-out", p7s, "-signer",
                                            dir_ / "ca.pem", "-inkey", dir_ / "ca.key"});
  }
  bool MakeCa() {
    return Openssl({"req", "-x509", "-newkey", "ec", "-pkeyopt", kCurve, "-nodes", "-keyout", dir_ / "ca.key", "-out",
                    dir_ / "ca.pem", "-days", std::to_string(o_.days), "-subj", OpensslSubject("turf CA")}) &&
           Private(dir_ / "ca.key");
  }
  bool MakeIdentity(const std::string& identity) {
    const fs::path d = dir_ / identity;
    std::error_code ec;
    fs::create_directories(d, ec);
    if (ec) {
      errors_.push_back(fmt::format("cannot create {}: {}", d.string(), ec.message()));
      return false;
    }
    const fs::path csr = d / "cert.csr";
    const bool ok = Openssl({"req", "-new", "-newkey", "ec", "-pkeyopt", kCurve, "-nodes", "-keyout", d / "key.pem",
                             "-out", csr, "-subj", OpensslSubject("turf " + identity)}) &&
                    Private(d / "key.pem") &&
                    Openssl({"x509", "-req", "-in", csr, "-CA", dir_ / "ca.pem", "-CAkey", dir_ / "ca.key",
                             "-CAcreateserial", "-out", d / "cert.pem", "-days", std::to_string(o_.days)}) &&
                    Copy(dir_ / "ca.pem", d / "ca.pem") && Copy(dir_ / "governance.p7s", d / "governance.p7s") &&
                    Signed(d / "permissions.xml", dds::PermissionsXml(identity, o_.profile, o_.prefix, DayFromToday(-1),
                                                                      DayFromToday(o_.days)));
    fs::remove(csr, ec);
    return ok;
  }
  bool Copy(const fs::path& from, const fs::path& to) {
    std::error_code ec;
    fs::copy_file(from, to, fs::copy_options::overwrite_existing, ec);
    if (!ec) return true;
    errors_.push_back(fmt::format("cannot copy {} to {}: {}", from.string(), to.string(), ec.message()));
    return false;
  }

  const SecurityInitOptions& o_;
  const fs::path dir_;
  std::vector<std::string> errors_;
};

}  // namespace

std::vector<std::string> InitSecurity(const SecurityInitOptions& options) { return Maker(options).Run(); }

}  // namespace turf::launch
