#pragma once

// Bytes in and out for snapshots: a writer, a reader that refuses to read past its end, and
// the archives every layer's records describe their fields to (one io() per record, used for
// both directions, so saving and loading cannot disagree on the order).

#include <array>
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <span>
#include <string>
#include <type_traits>
#include <utility>
#include <variant>
#include <vector>

#include "mink/error.hpp"
#include "mink/geometry/aabb.hpp"
#include "mink/geometry/types.hpp"

namespace mink {

/// A snapshot that cannot be restored: from another build or format version, truncated, or
/// corrupt. The message says which, and where (the byte offset for truncation).
class SnapshotError : public Error {
 public:
  using Error::Error;
};

/// A 64-bit hash of bytes, the same on every build and platform of the same byte order (state
/// hashes and snapshot checksums). Eight bytes at a time, each mixed in by a multiply.
inline std::uint64_t hash_bytes(std::span<const std::uint8_t> bytes,
                                std::uint64_t seed = 0x6d696e6b736e6170ULL) {
  constexpr std::uint64_t kMul = 0x9e3779b97f4a7c15ULL;
  std::uint64_t h = seed ^ (bytes.size() * kMul);
  const auto mix = [&](std::uint64_t word) {
    h ^= word * 0xbf58476d1ce4e5b9ULL;
    h = (h << 27 | h >> 37) * kMul;
  };
  std::size_t i = 0;
  for (; i + 8 <= bytes.size(); i += 8) {
    std::uint64_t word;
    std::memcpy(&word, bytes.data() + i, 8);
    mix(word);
  }
  std::uint64_t tail = 0;
  for (std::size_t k = 0; i + k < bytes.size(); ++k) {
    tail |= std::uint64_t{bytes[i + k]} << (8 * k);
  }
  mix(tail);
  h ^= h >> 31;
  h *= 0x94d049bb133111ebULL;
  return h ^ (h >> 29);
}

class ByteWriter {
 public:
  template <typename T>
  requires std::is_arithmetic_v<T> || std::is_enum_v<T>
  void value(T v) {
    if constexpr (std::is_same_v<T, bool>) {
      bytes_.push_back(v ? 1 : 0);
    } else {
      raw(&v, sizeof v);
    }
  }
  void raw(const void* data, std::size_t size) {
    if (size == 0) return;
    const std::size_t at = bytes_.size();
    bytes_.resize(at + size);
    std::memcpy(bytes_.data() + at, data, size);
  }
  std::vector<std::uint8_t>& bytes() noexcept { return bytes_; }

 private:
  std::vector<std::uint8_t> bytes_;
};

class ByteReader {
 public:
  /// @param base offset of `bytes` in the whole snapshot, for the messages
  explicit ByteReader(std::span<const std::uint8_t> bytes, std::size_t base = 0)
      : bytes_(bytes), base_(base) {}

  template <typename T>
  requires std::is_arithmetic_v<T> || std::is_enum_v<T>
  void value(T& v) {
    if constexpr (std::is_same_v<T, bool>) {
      std::uint8_t b = 0;
      raw(&b, 1);
      if (b > 1) fail("a flag that is neither 0 nor 1");
      v = b != 0;
    } else {
      raw(&v, sizeof v);
    }
  }
  template <typename T>
  T get() {
    T v{};
    value(v);
    return v;
  }
  void raw(void* data, std::size_t size) {
    if (size > remaining()) {
      throw SnapshotError("snapshot truncated at byte " + std::to_string(base_ + bytes_.size()) +
                          ": " + std::to_string(size) + " more bytes needed at byte " +
                          std::to_string(base_ + position_));
    }
    if (size != 0) std::memcpy(data, bytes_.data() + position_, size);
    position_ += size;
  }
  /// A count of elements of at least `min_element_size` bytes each, checked against what is
  /// left so that a corrupt count cannot ask for a huge allocation.
  std::size_t count(std::size_t min_element_size) {
    const std::uint64_t n = get<std::uint64_t>();
    if (n > remaining() / (min_element_size == 0 ? 1 : min_element_size)) {
      fail("a count of " + std::to_string(n) + " that the remaining " +
           std::to_string(remaining()) + " bytes cannot hold");
    }
    return static_cast<std::size_t>(n);
  }
  [[noreturn]] void fail(const std::string& what) const {
    throw SnapshotError("corrupt snapshot at byte " + std::to_string(base_ + position_) + ": " +
                        what);
  }
  std::size_t remaining() const noexcept { return bytes_.size() - position_; }
  std::size_t position() const noexcept { return base_ + position_; }

 private:
  std::span<const std::uint8_t> bytes_;
  std::size_t base_ = 0;
  std::size_t position_ = 0;
};

/// The archives: `archive(field)` writes or reads one field. Arithmetic and enum fields go
/// straight to the bytes; anything else through an io(archive, record) overload found by
/// argument-dependent lookup (declared next to the archives for library types, and in the
/// record's own namespace, or mink::detail, for the engine's).
template <typename Archive, typename T, typename Allocator>
void io(Archive& archive, std::vector<T, Allocator>& items);
template <typename Archive, typename T, std::size_t N>
void io(Archive& archive, std::array<T, N>& items);
template <typename Archive, typename... Ts>
void io(Archive& archive, std::variant<Ts...>& item);
template <typename Archive>
void io(Archive& archive, Vec2& v);
template <typename Archive>
void io(Archive& archive, Aabb& box);

struct SaveArchive {
  static constexpr bool loading = false;
  ByteWriter& out;
  template <typename T>
  void operator()(const T& field) {
    if constexpr (std::is_arithmetic_v<T> || std::is_enum_v<T>) {
      out.value(field);
    } else {
      io(*this, const_cast<T&>(field));
    }
  }
  void count(std::size_t n) { out.value(static_cast<std::uint64_t>(n)); }
};

struct LoadArchive {
  static constexpr bool loading = true;
  ByteReader& in;
  std::uint32_t world = 0;  // the serial that ids read get (ids are stored without theirs)
  template <typename T>
  void operator()(T& field) {
    if constexpr (std::is_arithmetic_v<T> || std::is_enum_v<T>) {
      in.value(field);
    } else {
      io(*this, field);
    }
  }
  std::size_t count(std::size_t min_element_size) { return in.count(min_element_size); }
};

template <typename Archive>
void io(Archive& archive, Vec2& v) {
  archive(v.x());
  archive(v.y());
}

template <typename Archive>
void io(Archive& archive, Aabb& box) {
  archive(box.lower);
  archive(box.upper);
}

template <typename Archive, typename T, typename Allocator>
void io(Archive& archive, std::vector<T, Allocator>& items) {
  constexpr bool plain = std::is_arithmetic_v<T> && !std::is_same_v<T, bool>;
  if constexpr (Archive::loading) {
    items.resize(archive.count(plain ? sizeof(T) : 1));
  } else {
    archive.count(items.size());
  }
  if constexpr (plain) {
    // Plain numbers have no padding: their bytes go as one block.
    if constexpr (Archive::loading) {
      archive.in.raw(items.data(), items.size() * sizeof(T));
    } else {
      archive.out.raw(items.data(), items.size() * sizeof(T));
    }
  } else {
    for (T& item : items) archive(item);
  }
}

template <typename Archive, typename T, std::size_t N>
void io(Archive& archive, std::array<T, N>& items) {
  for (T& item : items) archive(item);
}

template <typename Archive, typename... Ts>
void io(Archive& archive, std::variant<Ts...>& item) {
  std::uint32_t index = static_cast<std::uint32_t>(item.index());
  archive(index);
  if constexpr (Archive::loading) {
    if (index >= sizeof...(Ts)) {
      archive.in.fail("alternative " + std::to_string(index) + " of a " +
                      std::to_string(sizeof...(Ts)) + "-way choice");
    }
    // Make the alternative the bytes name, then read its fields.
    [&]<std::size_t... I>(std::index_sequence<I...>) {
      ((index == I ? (void)item.template emplace<I>() : (void)0), ...);
    }
    (std::index_sequence_for<Ts...>{});
  }
  std::visit([&](auto& alternative) { archive(alternative); }, item);
}

}  // namespace mink
