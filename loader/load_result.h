// What a scene loader returns: the compiled scene, or every error found.
#pragma once

#include <optional>
#include <string>
#include <vector>

namespace turf {

template <class T>
struct LoadResult {
  std::optional<T> scene;  // set only when there are no errors
  std::vector<std::string> errors;
};

}  // namespace turf
