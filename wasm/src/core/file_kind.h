// Files that are not meshes, told by their first bytes. Internal to the
// core: read_mesh and detect_format ask it first, so the app, the worker and
// the CLI all say "This is a PNG image" instead of quoting binary as a bad
// OFF header. Owner: file_kind.cpp.
#pragma once

#include <string>
#include <string_view>

#include "mesh_types.h"

namespace subdivlab::detail {

/// What `bytes` is when its first bytes (magic numbers) say it is a file of
/// another kind: "a PNG image", "a JPEG image", "a GIF image", "a PDF
/// document", "a ZIP archive (.zip, .docx, .3mf, ...)", "a glTF model",
/// "a binary glTF model (.glb)", "gzip-compressed data"; nullptr otherwise.
/// JSON glTF is an object with an "asset" member in its first 4 KiB.
const char* other_file_kind(std::string_view bytes);

/// ok, or the parse_error "This is a PNG image, not a mesh. SubdivLab reads
/// OFF, OBJ, PLY and STL." for other_file_kind's files.
Status check_not_other_file(std::string_view bytes);

/// A token of the file as messages quote it: at most 40 bytes, cut before a
/// UTF-8 sequence rather than inside it, and control bytes (NUL, ESC ...)
/// and bytes that are no UTF-8 text written as \xNN, so a file cannot put
/// terminal escapes, a NUL or undecodable bytes into the one-line error a
/// CLI prints.
std::string quoted(std::string_view tok);

/// quoted's text without the quotes (followed by "..." when cut), for a
/// name a message shows bare (a PLY element's, a rule set's host).
std::string printable(std::string_view tok);

/// How much of `bytes` is not text: of its first `sample` bytes (at most
/// 4 KiB), `non_text` are control bytes other than tab, line and page
/// breaks, or bytes outside valid UTF-8 sequences. A file whose share is
/// 10 % or more looks binary (looks_binary): compressed or random data
/// has about a third, binary STL's floats many NULs, while text with one
/// stray control byte stays text.
struct Text_share {
  std::size_t sample = 0, non_text = 0;
};
Text_share text_share(std::string_view bytes);
bool looks_binary(const Text_share& share);

/// Whether `bytes` is UTF-16 text (as Windows Notepad saves "Unicode"): a
/// byte-order mark, or, over its first 4 KiB, nine in ten byte pairs an
/// ASCII character beside a zero byte. Such a file is text in another
/// encoding, not a binary file, and a message says how to save it.
bool looks_utf16(std::string_view bytes);

/// The sentence naming the formats read, for messages.
inline constexpr const char* formats_read =
    "SubdivLab reads OFF, OBJ, PLY and STL.";

}  // namespace subdivlab::detail
