// Raw bytes in and out, for saved states and checkpoints. Values are stored
// in the machine's own layout: a state is read back by the same build on the
// same kind of machine (the header of each file checks this), which keeps a
// resumed run bit-identical to one that never stopped.
#pragma once

#include <cstdint>
#include <cstring>
#include <stdexcept>
#include <string>
#include <type_traits>
#include <vector>

namespace sim {

// A state file that is truncated, from another build, or not a state at all.
class StateError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

class BinaryWriter {
 public:
  BinaryWriter() = default;
  // Writes into `buffer`'s storage (its content is dropped): a state saved
  // again and again reuses its memory instead of faulting in fresh pages.
  explicit BinaryWriter(std::string buffer) : bytes_(std::move(buffer)) { bytes_.clear(); }

  template <class T>
  void put(const T& v) {
    static_assert(std::is_trivially_copyable<T>::value, "raw bytes only");
    bytes_.append(reinterpret_cast<const char*>(&v), sizeof v);
  }
  template <class T>
  void put_vector(const std::vector<T>& v) {
    static_assert(std::is_trivially_copyable<T>::value, "raw bytes only");
    put(std::uint64_t(v.size()));
    bytes_.append(reinterpret_cast<const char*>(v.data()), v.size() * sizeof(T));
  }
  // Room for an array of n values of T, after its size as put_vector writes
  // it, to be filled later through at(): the offset of its first byte.
  template <class T>
  std::size_t put_space(std::size_t n) {
    put(std::uint64_t(n));
    const std::size_t offset = bytes_.size();
    bytes_.resize(offset + n * sizeof(T));
    return offset;
  }
  char* at(std::size_t offset) { return &bytes_[offset]; }
  void put_string(const std::string& s) {
    put(std::uint64_t(s.size()));
    bytes_.append(s);
  }
  // Room for `n` bytes in all: a writer that knows its size about grows its
  // buffer once instead of by doubling, each time copying into fresh pages.
  void reserve(std::size_t n) { bytes_.reserve(n); }
  const std::string& bytes() const { return bytes_; }
  std::string take() { return std::move(bytes_); }

 private:
  std::string bytes_;
};

class BinaryReader {
 public:
  // `label` names the source in messages (a file name).
  BinaryReader(const std::string& bytes, std::string label)
      : bytes_(bytes), label_(std::move(label)) {}

  template <class T>
  T get() {
    static_assert(std::is_trivially_copyable<T>::value, "raw bytes only");
    T v;
    std::memcpy(&v, take(sizeof v), sizeof v);
    return v;
  }
  template <class T>
  std::vector<T> get_vector() {
    std::vector<T> v;
    get_vector_into(v);
    return v;
  }
  // The same into v, whose memory is reused where it is large enough.
  template <class T>
  void get_vector_into(std::vector<T>& v) {
    const std::uint64_t n = get<std::uint64_t>();
    if (n > (bytes_.size() - at_) / sizeof(T)) fail("an array runs past the end");
    v.resize(n);
    if (n > 0) std::memcpy(v.data(), take(n * sizeof(T)), n * sizeof(T));
  }
  // An array that must hold exactly `n` values.
  template <class T>
  std::vector<T> get_vector(std::size_t n, const char* what) {
    std::vector<T> v;
    get_vector_into(v, n, what);
    return v;
  }
  template <class T>
  void get_vector_into(std::vector<T>& v, std::size_t n, const char* what) {
    get_vector_into(v);
    if (v.size() != n)
      fail(std::string(what) + " holds " + std::to_string(v.size()) + " values, expected " +
           std::to_string(n));
  }
  std::string get_string() {
    const std::uint64_t n = get<std::uint64_t>();
    if (n > bytes_.size() - at_) fail("a string runs past the end");
    return std::string(take(n), n);
  }
  bool at_end() const { return at_ == bytes_.size(); }
  [[noreturn]] void fail(const std::string& what) const {
    throw StateError(label_ + ": " + what + " (at byte " + std::to_string(at_) + ")");
  }

 private:
  const char* take(std::size_t n) {
    if (n > bytes_.size() - at_) fail("truncated");
    const char* p = bytes_.data() + at_;
    at_ += n;
    return p;
  }
  const std::string& bytes_;
  std::string label_;
  std::size_t at_ = 0;
};

}  // namespace sim
