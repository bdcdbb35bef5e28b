// The byte format of state snapshots: a writer that appends values and a
// reader that checks every length and enum, because a snapshot read back from
// a file or another process is untrusted input. Values are stored in the
// host's byte order and doubles bit for bit, so a restored run continues
// exactly; a snapshot is for the same build of turf on the same kind of host.
// Structs are written field by field (never their padding), so equal states
// give equal bytes.
#pragma once

#include <cstdint>
#include <cstring>
#include <string>
#include <string_view>
#include <type_traits>
#include <vector>

namespace turf {

class StateWriter {
 public:
  template <class T>
  void Put(T value) {
    static_assert(std::is_arithmetic_v<T> || std::is_enum_v<T>, "fields one by one");
    Bytes(&value, sizeof(value));
  }
  void Bytes(const void* data, size_t size) {
    if (size > 0) bytes_.append(static_cast<const char*>(data), size);
  }
  void Str(std::string_view s) {
    Put<uint64_t>(s.size());
    Bytes(s.data(), s.size());
  }
  void Doubles(const std::vector<double>& v) {
    Put<uint64_t>(v.size());
    Bytes(v.data(), v.size() * sizeof(double));
  }
  // A section marker: a reader checks it, so a misaligned read fails early.
  void Tag(uint32_t tag) { Put(tag); }
  std::string Take() { return std::move(bytes_); }
  size_t size() const { return bytes_.size(); }

 private:
  std::string bytes_;
};

class StateReader {
 public:
  explicit StateReader(std::string_view bytes) : bytes_(bytes) {}

  // False once any read failed; the first failure is kept.
  bool ok() const { return error_ == nullptr; }
  const char* error() const { return error_ == nullptr ? "" : error_; }
  bool AtEnd() const { return pos_ == bytes_.size(); }
  void Fail(const char* why) {
    if (error_ == nullptr) error_ = why;
  }

  template <class T>
  T Get() {
    static_assert(std::is_arithmetic_v<T>, "enums through Enum()");
    T value{};
    Bytes(&value, sizeof(value));
    return value;
  }
  bool Bool() { return Get<uint8_t>() != 0; }
  // An enum stored as its underlying type; values at or past `count` fail.
  template <class E>
  E Enum(E count) {
    using U = std::underlying_type_t<E>;
    const U raw = Get<U>();
    if (raw >= static_cast<U>(count)) {
      Fail("enum value out of range");
      return E{};
    }
    return static_cast<E>(raw);
  }
  void Bytes(void* out, size_t size) {
    if (size == 0) return;
    if (!ok() || bytes_.size() - pos_ < size) {
      Fail("truncated");
      std::memset(out, 0, size);
      return;
    }
    std::memcpy(out, bytes_.data() + pos_, size);
    pos_ += size;
  }
  // A length prefix; more than `max` fails (no allocation from a bad length).
  size_t Count(size_t max) {
    const uint64_t n = Get<uint64_t>();
    if (n > max) {
      Fail("length out of range");
      return 0;
    }
    return static_cast<size_t>(n);
  }
  std::string Str(size_t max) {
    std::string s(Count(max), '\0');
    Bytes(s.data(), s.size());
    return s;
  }
  // Exactly `expected` doubles (a vector whose size the model fixes).
  void Doubles(std::vector<double>* out, size_t expected) {
    if (Count(expected) != expected) Fail("wrong vector length");
    out->resize(expected);
    Bytes(out->data(), expected * sizeof(double));
  }
  void Tag(uint32_t expected) {
    if (Get<uint32_t>() != expected) Fail("section tag mismatch");
  }

 private:
  std::string_view bytes_;
  size_t pos_ = 0;
  const char* error_ = nullptr;
};

// Section tags: four characters, readable in a hex dump.
constexpr uint32_t StateTag(const char (&s)[5]) {
  return static_cast<uint32_t>(s[0]) | static_cast<uint32_t>(s[1]) << 8 | static_cast<uint32_t>(s[2]) << 16 |
         static_cast<uint32_t>(s[3]) << 24;
}

}  // namespace turf
