// The byte format of state snapshots: a writer that appends values and a
// reader that checks every length and enum, because a snapshot read back from
// a file or another process is untrusted input. Values are stored in the
// host's byte order and doubles bit for bit, so a restored run continues
// exactly; a snapshot is for the same build of turf on the same kind of host.
// Structs are written field by field (never their padding), so equal states
// give equal bytes.
//
// A struct's fields are listed once, for both directions (cereal's serialize(),
// in small): `io(a, b, c)` saves them on a StateWriter and restores them on a
// StateReader. A class lists its fields in a static member template,
//   template <class Io, class Self> static void Fields(Io& io, Self& self);
// called from Save (Self const) and Restore; a plain struct in a free overload,
//   template <class Io> void Fields(Io& io, IoRef<Io, LinkParams> p);
// which `io(...)` also finds for a nested field. Also visited: arrays,
// std::optional (a presence flag first), std::pair, std::string (at most
// kMaxSnapshotString bytes), Eigen's fixed-size vectors and quaternions (finite
// on restore), vectors and maps (the length first, at most kMaxSnapshotItems,
// or as Sized()/Exactly() say; a map refuses a key twice). An enum is checked below its kCount, or below
// the count an EnumCount(E) overload next to it names, or InRange() gives;
// doubles that must be finite go through FiniteValue(); `io.Check(valid, why)`
// fails a restore on a combination no save writes.
#pragma once

#include <array>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <map>
#include <optional>
#include <string>
#include <string_view>
#include <type_traits>
#include <utility>
#include <vector>

namespace turf {

class StateWriter;
class StateReader;

inline constexpr size_t kMaxSnapshotString = 256;  // a name or message in a snapshot
inline constexpr size_t kMaxSnapshotItems = 4096;  // a vector or map without Sized(): robots, joints, moves

// The count an enum's values stay below: its kCount; an enum without one
// declares `constexpr E EnumCount(E)` next to it (found by ADL).
template <class E>
constexpr auto EnumCount(E) -> decltype(E::kCount) {
  return E::kCount;
}

// An enum field and the count its values stay below (a restore fails past it).
template <class E>
struct Ranged {
  E& value;
  std::remove_const_t<E> count;
};
template <class E>
Ranged<E> InRange(E& value, std::remove_const_t<E> count) {
  return {value, count};
}

// A double field (or array of doubles) that a restore requires to be finite.
template <class D>
struct FiniteField {
  D& value;
};
template <class D>
FiniteField<D> FiniteValue(D& value) {
  return {value};
}

// A vector or map field, its length first; a restore fails past `max` elements
// (kMaxSnapshotItems without Sized()), or (Exactly) on any length but `n` (a
// vector whose size the model fixes).
template <class V>
struct SizedField {
  V& items;
  size_t max;
  bool exact;
};
template <class V>
SizedField<V> Sized(V& items, size_t max) {
  return {items, max, false};
}
template <class V>
SizedField<V> Exactly(V& items, size_t n) {
  return {items, n, true};
}

// The field type an Io visits: const when saving.
template <class Io, class T>
using IoRef = std::conditional_t<Io::kSaving, const T&, T&>;

template <class T, class = void>
struct HasSaveRestore : std::false_type {};
template <class T>
struct HasSaveRestore<T, std::void_t<decltype(&T::Save), decltype(&T::Restore)>> : std::true_type {};

// Eigen's fixed-size vectors (their coefficients) and quaternions (x, y, z, w), told apart without Eigen.
template <class T, class = void>
struct IsFixedVector : std::false_type {};
template <class T>
struct IsFixedVector<T, std::enable_if_t<(T::SizeAtCompileTime > 0)>> : std::true_type {};
template <class T, class = void>
struct IsQuaternion : std::false_type {};
template <class T>
struct IsQuaternion<T, std::void_t<decltype(std::declval<T&>().coeffs()), decltype(std::declval<T&>().w())>>
    : std::true_type {};

template <class T, class = void>
struct IsMap : std::false_type {};
template <class T>
struct IsMap<T, std::void_t<typename T::key_type, typename T::mapped_type>> : std::true_type {};

class StateWriter {
 public:
  static constexpr bool kSaving = true;

  // Saves the fields in order (see the top of this file).
  template <class... T>
  void operator()(const T&... fields) {
    (Field(fields), ...);
  }
  void Check(bool /*valid*/, const char* /*why*/) {}

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
  template <class T>
  void Field(const T& v) {
    if constexpr (std::is_arithmetic_v<T> || std::is_enum_v<T>) {
      Put(v);
    } else if constexpr (IsQuaternion<T>::value) {
      for (int k = 0; k < 4; ++k) Put(v.coeffs()[k]);
    } else if constexpr (IsFixedVector<T>::value) {
      for (int k = 0; k < T::SizeAtCompileTime; ++k) Put(v[k]);
    } else if constexpr (HasSaveRestore<T>::value) {
      v.Save(*this);
    } else {
      Fields(*this, v);
    }
  }
  void Field(const std::string& v) { Str(v); }
  template <class T, size_t N>
  void Field(const std::array<T, N>& v) {
    for (const T& x : v) Field(x);
  }
  template <class T, size_t N>
  void Field(const T (&v)[N]) {
    for (const T& x : v) Field(x);
  }
  template <class T>
  void Field(const std::optional<T>& v) {
    Put(v.has_value());
    if (v) Field(*v);
  }
  template <class A, class B>
  void Field(const std::pair<A, B>& v) {
    Field(v.first);
    Field(v.second);
  }
  template <class E>
  void Field(const Ranged<E>& r) {
    Put(r.value);
  }
  template <class D>
  void Field(const FiniteField<D>& f) {
    Field(f.value);
  }
  template <class T, class A>
  void Field(const std::vector<T, A>& v) {
    Field(Sized(v, kMaxSnapshotItems));
  }
  template <class K, class T, class C, class A>
  void Field(const std::map<K, T, C, A>& v) {
    Field(Sized(v, kMaxSnapshotItems));
  }
  template <class V>
  void Field(const SizedField<V>& v) {
    Put<uint64_t>(v.items.size());
    for (const auto& x : v.items) Field(x);
  }

  std::string bytes_;
};

class StateReader {
 public:
  static constexpr bool kSaving = false;

  explicit StateReader(std::string_view bytes) : bytes_(bytes) {}

  // Restores the fields in order (see the top of this file).
  template <class... T>
  void operator()(T&&... fields) {
    (Field(fields), ...);
  }
  // Fails the restore with `why` unless `valid` (checked once the fields read so far are whole).
  void Check(bool valid, const char* why) {
    if (ok() && !valid) Fail(why);
  }

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
  template <class T>
  void Field(T& v) {
    if constexpr (std::is_same_v<T, bool>) {
      v = Bool();
    } else if constexpr (std::is_enum_v<T>) {
      v = Enum(EnumCount(v));
    } else if constexpr (std::is_arithmetic_v<T>) {
      v = Get<T>();
    } else if constexpr (IsQuaternion<T>::value) {
      for (int k = 0; k < 4; ++k) v.coeffs()[k] = Finite();
    } else if constexpr (IsFixedVector<T>::value) {
      for (int k = 0; k < T::SizeAtCompileTime; ++k) v[k] = Finite();
    } else if constexpr (HasSaveRestore<T>::value) {
      v.Restore(*this);
    } else {
      Fields(*this, v);
    }
  }
  void Field(std::string& v) { v = Str(kMaxSnapshotString); }
  template <class T, size_t N>
  void Field(std::array<T, N>& v) {
    for (T& x : v) Field(x);
  }
  template <class T, size_t N>
  void Field(T (&v)[N]) {
    for (T& x : v) Field(x);
  }
  template <class T>
  void Field(std::optional<T>& v) {
    v.reset();
    if (!Bool()) return;
    Field(v.emplace());
  }
  template <class A, class B>
  void Field(std::pair<A, B>& v) {
    Field(v.first);
    Field(v.second);
  }
  double Finite() {
    const double v = Get<double>();
    if (!std::isfinite(v)) Fail("value not finite");
    return v;
  }
  template <class E>
  void Field(Ranged<E>& r) {
    r.value = Enum(r.count);
  }
  template <class D>
  void Field(FiniteField<D>& f) {
    if constexpr (std::is_arithmetic_v<D>) {
      f.value = Finite();
    } else {
      for (auto& x : f.value) x = Finite();
    }
  }
  template <class T, class A>
  void Field(std::vector<T, A>& v) {
    SizedField<std::vector<T, A>> sized = Sized(v, kMaxSnapshotItems);
    Field(sized);
  }
  template <class K, class T, class C, class A>
  void Field(std::map<K, T, C, A>& v) {
    SizedField<std::map<K, T, C, A>> sized = Sized(v, kMaxSnapshotItems);
    Field(sized);
  }
  template <class V>
  void Field(SizedField<V>& v) {
    const size_t n = Count(v.max);
    if (v.exact && n != v.max) Fail("wrong vector length");
    if constexpr (IsMap<V>::value) {
      v.items.clear();
      for (size_t i = 0; i < n && ok(); ++i) {
        std::pair<typename V::key_type, typename V::mapped_type> item;
        Field(item);
        if (!v.items.insert(std::move(item)).second) Fail("a key twice");
      }
    } else {
      v.items.resize(v.exact ? v.max : n);
      for (auto& x : v.items) Field(x);
    }
  }

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
