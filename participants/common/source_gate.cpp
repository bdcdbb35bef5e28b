#include "participants/common/source_gate.h"

#include <spdlog/spdlog.h>

#include <utility>

namespace turf {

namespace {

std::optional<AddressAllowlist> MakeList(const std::string& name, const std::vector<std::string>& entries) {
  if (entries.empty()) return std::nullopt;
  try {
    return AddressAllowlist(entries);
  } catch (const std::invalid_argument& e) {
    throw std::invalid_argument(name + " " + e.what());
  }
}

}  // namespace

SourceGate::SourceGate(std::string name, const std::vector<std::string>& entries)
    : name_(std::move(name)), kind_(name_ + ".not_allowed"), list_(MakeList(name_, entries)) {}

bool SourceGate::Admit(const UdpEndpoint& from, RejectLog& rejects, const std::string& kind) {
  if (Allows(from)) return true;
  refused_.fetch_add(1);
  rejects.Reject(kind, fmt::format("from {}: not on the {} allowlist ({})", from.ToString(), name_, Describe()));
  return false;
}

std::string SourceGate::Describe() const { return list_ ? list_->Describe() : "anyone"; }

void SourceGates::ReportStartup(const std::string& operator_use) const {
  spdlog::info("sources allowed: blue from {}; yellow from {}; {} from {}", blue.Describe(), yellow.Describe(),
               operator_use, operators.Describe());
}

}  // namespace turf
