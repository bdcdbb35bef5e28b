// A base for objects that are referred to by address once made (they own threads, sockets, MuJoCo buffers or
// callbacks into themselves): they can be neither copied nor moved. `class World : Pinned {` says it once.
#pragma once

namespace turf {

class Pinned {
 public:
  Pinned(const Pinned&) = delete;
  Pinned& operator=(const Pinned&) = delete;

 protected:
  Pinned() = default;
  ~Pinned() = default;
};

}  // namespace turf
