// The errors of a decoder's issues (any type with an `error` member), in order, to compare with a list in one
// assertion.
#pragma once

#include <vector>

#include "core/errors.h"

namespace turf::test {

template <class Issue>
std::vector<Error> ErrorsOf(const std::vector<Issue>& issues) {
  std::vector<Error> out;
  for (const Issue& i : issues) out.push_back(i.error);
  return out;
}

}  // namespace turf::test
