// Number formatting and chunked output shared by the mesh writers (OFF,
// OBJ, PLY, STL). Internal to the core. Owner: text_writer.cpp.
#pragma once

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <string_view>
#include <vector>

#include "mesh_io.h"

namespace subdivlab::detail {

/// x as printf("%.17g", x) writes it, at `out`; returns the end (at most 24
/// characters later).
char* write_g17(double x, char* out);

/// x in decimal at `out`; returns the end (at most 20 characters later).
char* write_uint(std::uint64_t x, char* out);

/// Text collected in a buffer of `capacity` bytes and handed to the sink
/// whenever the next token might not fit.
class Chunk_writer {
 public:
  /// Longest piece put() may be asked for: a number with its separator.
  static constexpr std::size_t max_piece = 32;

  Chunk_writer(std::size_t capacity, const Chunk_sink& sink)
      : buffer_(capacity), sink_(sink) {}

  /// Where the next piece (at most max_piece bytes) goes; commit() its end.
  char* reserve() {
    if (buffer_.size() - used_ < max_piece) flush();
    return buffer_.data() + used_;
  }
  void commit(char* end) {
    used_ = static_cast<std::size_t>(end - buffer_.data());
  }
  bool ok() const { return ok_; }

  /// Text of any length, in pieces of at most max_piece bytes.
  void put(std::string_view text) {
    while (!text.empty()) {
      const std::size_t n = std::min(text.size(), max_piece);
      char* p = reserve();
      std::memcpy(p, text.data(), n);
      commit(p + n);
      text.remove_prefix(n);
    }
  }

  /// Hands over what is left; false if the sink stopped the writing.
  bool finish() {
    flush();
    return ok_;
  }

 private:
  void flush() {
    if (used_ > 0 && ok_) ok_ = sink_(std::string_view(buffer_.data(), used_));
    used_ = 0;
  }

  std::vector<char> buffer_;
  std::size_t used_ = 0;
  const Chunk_sink& sink_;
  bool ok_ = true;
};

}  // namespace subdivlab::detail
