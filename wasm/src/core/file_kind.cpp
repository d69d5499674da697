// Magic numbers of the files people drop by mistake. Owner of file_kind.h.

#include "file_kind.h"

#include <algorithm>
#include <cstdio>
#include <string>

namespace subdivlab::detail {
namespace {

bool starts_with(std::string_view bytes, std::string_view magic) {
  return bytes.substr(0, magic.size()) == magic;
}

/// A JSON object (after blanks and a UTF-8 byte order mark) with an
/// "asset" key early on: glTF's one required member.
bool is_gltf_json(std::string_view bytes) {
  if (starts_with(bytes, "\xEF\xBB\xBF")) bytes.remove_prefix(3);
  const std::size_t first = bytes.find_first_not_of(" \t\r\n");
  if (first == std::string_view::npos || bytes[first] != '{') return false;
  return bytes.substr(0, 4096).find("\"asset\"") != std::string_view::npos;
}

/// Length of the valid UTF-8 sequence at `p` (1 for ASCII), or 0 when the
/// bytes there are none (a stray continuation byte, a lead byte without its
/// continuations, or cut by `end`).
std::size_t utf8_length(const unsigned char* p, const unsigned char* end) {
  const unsigned char u = *p;
  std::size_t n = 0;
  if (u < 0x80) return 1;
  if (u >= 0xC2 && u <= 0xDF)
    n = 2;
  else if (u >= 0xE0 && u <= 0xEF)
    n = 3;
  else if (u >= 0xF0 && u <= 0xF4)
    n = 4;
  else
    return 0;
  if (static_cast<std::size_t>(end - p) < n) return 0;
  for (std::size_t k = 1; k < n; ++k)
    if ((p[k] & 0xC0) != 0x80) return 0;
  return n;
}

bool is_control(unsigned char u) {
  return (u < 0x20 && u != '\t' && u != '\n' && u != '\r' && u != '\f' &&
          u != '\v') ||
         u == 0x7F;
}

}  // namespace

Text_share text_share(std::string_view bytes) {
  Text_share share;
  share.sample = std::min<std::size_t>(bytes.size(), 4096);
  const auto* p = reinterpret_cast<const unsigned char*>(bytes.data());
  const auto* end = p + share.sample;
  while (p < end) {
    const std::size_t n = utf8_length(p, end);
    // A sequence cut by the sample's end is not counted against the file.
    if (n == 0 && static_cast<std::size_t>(end - p) < 4 &&
        share.sample < bytes.size())
      break;
    if (n == 0 || (n == 1 && is_control(*p))) ++share.non_text;
    p += n == 0 ? 1 : n;
  }
  return share;
}

bool looks_binary(const Text_share& share) {
  return share.sample > 0 && 10 * share.non_text >= share.sample;
}

bool looks_utf16(std::string_view bytes) {
  if (bytes.substr(0, 2) == "\xFF\xFE" || bytes.substr(0, 2) == "\xFE\xFF")
    return true;
  const std::size_t pairs = std::min<std::size_t>(bytes.size(), 4096) / 2;
  if (pairs < 4) return false;
  const auto ascii = [](unsigned char c) {
    return c == '\t' || c == '\n' || c == '\r' || (c >= 0x20 && c < 0x7F);
  };
  std::size_t little = 0, big = 0;
  for (std::size_t i = 0; i < pairs; ++i) {
    const auto a = static_cast<unsigned char>(bytes[2 * i]);
    const auto b = static_cast<unsigned char>(bytes[2 * i + 1]);
    little += ascii(a) && b == 0;
    big += a == 0 && ascii(b);
  }
  return 10 * std::max(little, big) >= 9 * pairs;
}

std::string quoted(std::string_view tok) { return "'" + printable(tok) + "'"; }

std::string printable(std::string_view tok) {
  constexpr std::size_t max = 40;
  std::size_t n = std::min(tok.size(), max);
  // A UTF-8 sequence has at most 3 continuation bytes (10xxxxxx).
  for (int back = 0; back < 3 && n > 0 && n < tok.size() &&
                     (static_cast<unsigned char>(tok[n]) & 0xC0) == 0x80;
       ++back)
    --n;
  std::string s;
  const auto* p = reinterpret_cast<const unsigned char*>(tok.data());
  // Up to the end of the token, so that a sequence cut at n is whole here.
  const auto* end = p + tok.size();
  for (std::size_t i = 0; i < n;) {
    const std::size_t k = utf8_length(p + i, end);
    if (k == 0 || (k == 1 && (p[i] < 0x20 || p[i] == 0x7F))) {
      char buf[8];
      std::snprintf(buf, sizeof buf, "\\x%02X", p[i]);
      s += buf;
      ++i;
    } else {
      s.append(tok.substr(i, k));
      i += k;
    }
  }
  if (n < tok.size()) s += "...";
  return s;
}

const char* other_file_kind(std::string_view bytes) {
  if (starts_with(bytes, "\x89PNG\r\n\x1A\n")) return "a PNG image";
  if (starts_with(bytes, "\xFF\xD8\xFF")) return "a JPEG image";
  if (starts_with(bytes, "GIF87a") || starts_with(bytes, "GIF89a"))
    return "a GIF image";
  if (starts_with(bytes, "%PDF-")) return "a PDF document";
  if (starts_with(bytes, "PK\x03\x04") || starts_with(bytes, "PK\x05\x06"))
    return "a ZIP archive (.zip, .docx, .3mf, ...)";
  if (starts_with(bytes, "glTF")) return "a binary glTF model (.glb)";
  if (starts_with(bytes, "\x1F\x8B")) return "gzip-compressed data";
  if (is_gltf_json(bytes)) return "a glTF model";
  return nullptr;
}

Status check_not_other_file(std::string_view bytes) {
  const char* kind = other_file_kind(bytes);
  if (!kind) return Status::success();
  std::string what = std::string("This is ") + kind + ", not a mesh. ";
  if (std::string_view(kind).find("gzip") != std::string_view::npos)
    what = "This is gzip-compressed data, not a mesh: unpack it first. ";
  return Status::error(Status_code::parse_error, what + formats_read);
}

}  // namespace subdivlab::detail
