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

}  // namespace

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
  for (const char c : tok.substr(0, n)) {
    const auto u = static_cast<unsigned char>(c);
    if (u < 0x20 || u == 0x7F) {
      char buf[8];
      std::snprintf(buf, sizeof buf, "\\x%02X", u);
      s += buf;
    } else {
      s += c;
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
