// OFF and OBJ text in and out.
//
// Both readers are line based: every error names the 1-based line it was
// found on, and a header's counts are trusted only as far as the text backs
// them (reserve never exceeds what the remaining bytes could hold). After
// parsing, the buffers go through the same checks as build_mesh
// (detail::check_buffers) with faces named by their lines, and isolated
// vertices are dropped as build_mesh drops them.

#include "mesh_io.h"

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <new>
#include <string>
#include <string_view>
#include <vector>

#include "mesh_check.h"

namespace subdivlab {
namespace {

// ---------------------------------------------------------------- lexing

/// Yields the lines of a text: "\n", "\r\n" and lone "\r" end a line, a
/// leading UTF-8 byte order mark is skipped, and a '#' starts a comment.
class Line_reader {
 public:
  explicit Line_reader(std::string_view text) : text_(text) {
    if (text_.substr(0, 3) == "\xEF\xBB\xBF") pos_ = 3;
  }

  /// Next line that holds anything but blanks and comments; false at the
  /// end. `line` is its 1-based number.
  bool next(std::vector<std::string_view>& tokens, int& line) {
    while (pos_ < text_.size()) {
      const std::size_t begin = pos_;
      std::size_t end = begin;
      while (end < text_.size() && text_[end] != '\n' && text_[end] != '\r')
        ++end;
      pos_ = end;
      if (pos_ < text_.size()) {
        const bool crlf = text_[pos_] == '\r' && pos_ + 1 < text_.size() &&
                          text_[pos_ + 1] == '\n';
        pos_ += crlf ? 2 : 1;
      }
      ++line_;
      std::string_view content = text_.substr(begin, end - begin);
      const std::size_t hash = content.find('#');
      if (hash != std::string_view::npos) content = content.substr(0, hash);
      split(content, tokens);
      if (!tokens.empty()) {
        line = line_;
        return true;
      }
    }
    return false;
  }

  /// Number of the last line of the text (where "the file ends").
  int last_line() const { return line_ == 0 ? 1 : line_; }

  /// Bytes not read yet; bounds what any declared count may reserve.
  std::size_t remaining() const { return text_.size() - pos_; }

 private:
  static bool is_blank(char c) {
    return c == ' ' || c == '\t' || c == '\v' || c == '\f' || c == '\r';
  }
  static void split(std::string_view s, std::vector<std::string_view>& tokens) {
    tokens.clear();
    std::size_t i = 0;
    while (i < s.size()) {
      while (i < s.size() && is_blank(s[i])) ++i;
      const std::size_t b = i;
      while (i < s.size() && !is_blank(s[i])) ++i;
      if (i > b) tokens.push_back(s.substr(b, i - b));
    }
  }

  std::string_view text_;
  std::size_t pos_ = 0;
  int line_ = 0;
};

enum class Number { ok, not_number, not_finite };

/// Strict decimal floating point: the whole token must be a number such as
/// "1", "-0.5", "1e5" or ".5". "inf"/"nan" and values beyond the double
/// range are non-finite; hex floats, "1.2.3" and "abc" are not numbers.
/// strtod on a bounded, NUL-terminated copy: libc++ in em++ 3.1.6 has no
/// floating-point std::from_chars.
Number parse_double(std::string_view tok, double& out) {
  if (tok.empty() || tok.size() > 400) return Number::not_number;
  std::string_view body = tok;
  if (body[0] == '+' || body[0] == '-') body.remove_prefix(1);
  std::string lower(body);
  for (char& c : lower)
    c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  if (lower == "inf" || lower == "infinity" || lower == "nan" ||
      lower.rfind("nan(", 0) == 0) {
    return Number::not_finite;
  }
  for (char c : tok) {
    const bool ok = (c >= '0' && c <= '9') || c == '.' || c == 'e' ||
                    c == 'E' || c == '+' || c == '-';
    if (!ok) return Number::not_number;
  }
  char buf[408];
  std::copy(tok.begin(), tok.end(), buf);
  buf[tok.size()] = '\0';
  char* end = nullptr;
  errno = 0;
  const double v = std::strtod(buf, &end);
  if (end != buf + tok.size()) return Number::not_number;
  if (!std::isfinite(v)) return Number::not_finite;
  out = v;
  return Number::ok;
}

/// Strict decimal integer with optional sign; false if not an integer.
/// Magnitudes beyond 10^18 saturate there: every caller treats such a value
/// as out of range and quotes the token itself.
bool parse_int(std::string_view tok, long long& out) {
  constexpr long long cap = 1000000000000000000ll;
  std::size_t i = 0;
  bool neg = false;
  if (i < tok.size() && (tok[i] == '+' || tok[i] == '-')) neg = tok[i++] == '-';
  if (i == tok.size()) return false;
  long long v = 0;
  for (; i < tok.size(); ++i) {
    if (tok[i] < '0' || tok[i] > '9') return false;
    v = v >= cap / 10 ? cap : v * 10 + (tok[i] - '0');
  }
  out = neg ? -v : v;
  return true;
}

std::string at(int line) { return "line " + std::to_string(line) + ": "; }
/// A token of the file as messages quote it: at most 40 bytes, cut before a
/// UTF-8 sequence rather than inside it, and control bytes (NUL, ESC ...)
/// written as \xNN, so a file cannot put terminal escapes or a NUL into the
/// one-line error a CLI prints.
std::string quoted(std::string_view tok) {
  constexpr std::size_t max = 40;
  std::size_t n = std::min(tok.size(), max);
  // A UTF-8 sequence has at most 3 continuation bytes (10xxxxxx).
  for (int back = 0; back < 3 && n > 0 && n < tok.size() &&
                     (static_cast<unsigned char>(tok[n]) & 0xC0) == 0x80;
       ++back)
    --n;
  std::string s = "'";
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
  return s + "'";
}

Result<Mesh_buffers> parse_fail(int line, const std::string& what) {
  Result<Mesh_buffers> r;
  r.status = Status::error(Status_code::parse_error,
                           (line > 0 ? at(line) : "") + what, line);
  return r;
}

/// Reads one coordinate; on failure fills `r` with the reason.
bool read_coordinate(std::string_view tok, int line, const std::string& what,
                     double& out, Result<Mesh_buffers>& r) {
  switch (parse_double(tok, out)) {
    case Number::ok:
      return true;
    case Number::not_finite:
      r = parse_fail(line, what + " is not finite: " + quoted(tok));
      return false;
    case Number::not_number:
      r = parse_fail(line, what + " is not a number: " + quoted(tok));
      return false;
  }
  return false;
}

const char* const axis_name[3] = {"x", "y", "z"};

/// The checks build_mesh makes, with faces named by their lines; then the
/// isolated vertices go.
Result<Mesh_buffers> finish(Mesh_buffers&& mesh,
                            const std::vector<int>& face_lines,
                            std::uint32_t vertex_offset) {
  detail::Check_naming naming;
  naming.face_lines = &face_lines;
  naming.vertex_offset = vertex_offset;
  Result<Mesh_buffers> r;
  detail::Check_result check = detail::check_buffers(mesh, naming);
  if (!check.status.ok()) {
    r.status = std::move(check.status);
    return r;
  }
  r.value = detail::drop_isolated_vertices(mesh);
  return r;
}

// ---------------------------------------------------------------- OFF

Result<Mesh_buffers> read_off(std::string_view text) {
  Line_reader in(text);
  std::vector<std::string_view> tok;
  int line = 0;
  if (!in.next(tok, line))
    return parse_fail(0, "the file is empty: no OFF header");

  // Header keyword: [ST][C][N][4][n]OFF, optionally followed by the counts.
  std::string_view key = tok[0];
  bool normals = false, colours = false, texture = false;
  {
    std::string_view k = key;
    if (k.substr(0, 2) == "ST") texture = true, k.remove_prefix(2);
    if (k.substr(0, 1) == "C") colours = true, k.remove_prefix(1);
    if (k.substr(0, 1) == "N") normals = true, k.remove_prefix(1);
    if (k == "4OFF" || k == "4nOFF") {
      return parse_fail(line,
                        "4D OFF (" + std::string(key) +
                            ") is not supported: SubdivLab reads 3D meshes");
    }
    if (k == "nOFF") {
      return parse_fail(line,
                        "nOFF (" + std::string(key) +
                            ", dimension given in the file) is not supported");
    }
    if (k != "OFF") {
      return parse_fail(
          line, "unknown OFF header " + quoted(key) +
                    " (expected OFF, COFF, NOFF, CNOFF, STOFF or another "
                    "[ST][C][N]OFF variant)");
    }
  }
  std::size_t c0 = 1;
  if (tok.size() > 1 && tok[1] == "BINARY") {
    return parse_fail(line,
                      "binary OFF is not supported; save the mesh as text OFF");
  }
  if (tok.size() == 1) {
    if (!in.next(tok, line))
      return parse_fail(in.last_line(), "file ends before the counts line");
    c0 = 0;
  }
  const std::size_t n_counts = tok.size() - c0;
  if (n_counts < 2 || n_counts > 3) {
    return parse_fail(line,
                      "expected the counts 'vertices faces edges', found " +
                          std::to_string(n_counts) + " values");
  }
  long long nv_ll = 0, nf_ll = 0, ne_ll = 0;
  const char* count_name[3] = {"vertex", "face", "edge"};
  long long* count_val[3] = {&nv_ll, &nf_ll, &ne_ll};
  for (std::size_t i = 0; i < n_counts; ++i) {
    if (!parse_int(tok[c0 + i], *count_val[i]) || *count_val[i] < 0) {
      return parse_fail(line, std::string(count_name[i]) + " count " +
                                  quoted(tok[c0 + i]) +
                                  " is not a non-negative integer");
    }
  }
  if (nv_ll > 0xfffffffell)
    return parse_fail(line,
                      "vertex count " + std::string(tok[c0]) + " is too large");
  if (nf_ll > 0xfffffffell)
    return parse_fail(
        line, "face count " + std::string(tok[c0 + 1]) + " is too large");
  const std::size_t nv = static_cast<std::size_t>(nv_ll),
                    nf = static_cast<std::size_t>(nf_ll);

  // Each vertex takes at least "0 0 0\n", each face "3 0 1 2\n": a count the
  // remaining text cannot hold must not reserve memory.
  Mesh_buffers mesh;
  const std::size_t left = in.remaining();
  mesh.positions.reserve(3 * std::min(nv, left / 6 + 1));
  mesh.face_sizes.reserve(std::min(nf, left / 8 + 1));
  mesh.face_indices.reserve(
      std::min<std::uint64_t>(3 * std::uint64_t(nf), left / 2 + 1));
  std::vector<int> face_lines;
  face_lines.reserve(mesh.face_sizes.capacity());

  const std::size_t min_values =
      3 + (normals ? 3 : 0) + (colours ? 3 : 0) + (texture ? 2 : 0);
  for (std::size_t v = 0; v < nv; ++v) {
    if (!in.next(tok, line)) {
      return parse_fail(in.last_line(), "file ends after " + std::to_string(v) +
                                            " of " + std::to_string(nv) +
                                            " vertices");
    }
    if (tok.size() < min_values) {
      std::string need = "x y z";
      if (normals) need += ", a normal";
      if (colours) need += ", a colour";
      if (texture) need += ", texture coordinates";
      return parse_fail(line, "vertex " + std::to_string(v) + " has " +
                                  std::to_string(tok.size()) + " values; " +
                                  std::string(key) + " needs at least " +
                                  std::to_string(min_values) + " (" + need +
                                  ")");
    }
    for (int a = 0; a < 3; ++a) {
      double x = 0;
      Result<Mesh_buffers> r;
      if (!read_coordinate(tok[a], line,
                           std::string(axis_name[a]) +
                               " coordinate of vertex " + std::to_string(v),
                           x, r)) {
        return r;
      }
      mesh.positions.push_back(x);
    }
    // Normals, colours, texture coordinates: numbers the core does not keep.
    for (std::size_t i = 3; i < tok.size(); ++i) {
      double x = 0;
      if (parse_double(tok[i], x) == Number::not_number) {
        return parse_fail(line, "value " + std::to_string(i + 1) +
                                    " of vertex " + std::to_string(v) +
                                    " is not a number: " + quoted(tok[i]));
      }
    }
  }

  for (std::size_t f = 0; f < nf; ++f) {
    if (!in.next(tok, line)) {
      return parse_fail(in.last_line(), "file ends after " + std::to_string(f) +
                                            " of " + std::to_string(nf) +
                                            " faces");
    }
    long long k = 0;
    if (!parse_int(tok[0], k) || k < 0) {
      return parse_fail(line, "face " + std::to_string(f) +
                                  " must start with its vertex count, found " +
                                  quoted(tok[0]) +
                                  " (do the header counts match the data?)");
    }
    const std::size_t listed = tok.size() - 1;
    if (static_cast<unsigned long long>(k) > listed) {
      return parse_fail(line, "face " + std::to_string(f) + " declares " +
                                  std::string(tok[0]) +
                                  " vertices but lists only " +
                                  std::to_string(listed));
    }
    const std::size_t extra = listed - static_cast<std::size_t>(k);
    if (extra > 4) {
      return parse_fail(
          line,
          "face " + std::to_string(f) + " declares " + std::string(tok[0]) +
              " vertices but the line has " + std::to_string(extra) +
              " more values (at most 4, a colour, may follow the indices)");
    }
    for (std::size_t i = 1; i <= static_cast<std::size_t>(k); ++i) {
      long long index = 0;
      if (!parse_int(tok[i], index)) {
        return parse_fail(
            line, "face index " + quoted(tok[i]) + " is not an integer");
      }
      if (index < 0 || static_cast<unsigned long long>(index) >= nv) {
        Result<Mesh_buffers> r;
        r.status = Status::error(
            Status_code::invalid_mesh,
            at(line) + "face index " + std::string(tok[i]) +
                " is out of range (" + std::to_string(nv) + " vertices)",
            line);
        return r;
      }
      mesh.face_indices.push_back(static_cast<std::uint32_t>(index));
    }
    for (std::size_t i = 1 + static_cast<std::size_t>(k); i < tok.size(); ++i) {
      double x = 0;
      if (parse_double(tok[i], x) == Number::not_number) {
        return parse_fail(line, "colour value of face " + std::to_string(f) +
                                    " is not a number: " + quoted(tok[i]));
      }
    }
    mesh.face_sizes.push_back(static_cast<std::uint32_t>(k));
    face_lines.push_back(line);
  }
  if (in.next(tok, line)) {
    return parse_fail(line, "extra data after the " + std::to_string(nf) +
                                " faces the header declares (header counts "
                                "disagree with the data)");
  }
  return finish(std::move(mesh), face_lines, 0);
}

// ---------------------------------------------------------------- OBJ

/// Statements that carry nothing the core needs (materials, groups,
/// smoothing, texture and normal data, lines, points, free-form geometry).
bool is_ignored_obj_statement(std::string_view k) {
  static const char* const ignored[] = {
      "o",         "g",        "s",        "usemtl", "mtllib", "l",
      "p",         "vt",       "vn",       "vp",     "mg",     "lod",
      "bevel",     "c_interp", "d_interp", "usemap", "maplib", "shadow_obj",
      "trace_obj", "ctech",    "stech",    "cstype", "deg",    "bmat",
      "step",      "curv",     "curv2",    "surf",   "parm",   "trim",
      "hole",      "scrv",     "sp",       "end",    "con"};
  for (const char* s : ignored) {
    if (k == s) return true;
  }
  return false;
}

/// One corner of an OBJ face: "v", "v/vt", "v//vn" or "v/vt/vn"; only v is
/// kept. Returns false when the token has another form.
bool parse_obj_corner(std::string_view t, long long& v) {
  const std::size_t s1 = t.find('/');
  if (!parse_int(t.substr(0, s1), v)) return false;
  if (s1 == std::string_view::npos) return true;
  std::string_view rest = t.substr(s1 + 1);
  const std::size_t s2 = rest.find('/');
  const std::string_view vt = rest.substr(0, s2);
  long long dummy = 0;
  if (s2 == std::string_view::npos) return parse_int(vt, dummy);  // v/vt
  const std::string_view vn = rest.substr(s2 + 1);
  if (!vt.empty() && !parse_int(vt, dummy)) return false;
  return parse_int(vn, dummy);  // v//vn or v/vt/vn
}

Result<Mesh_buffers> read_obj(std::string_view text) {
  Line_reader in(text);
  std::vector<std::string_view> tok;
  int line = 0;
  Mesh_buffers mesh;
  std::vector<int> face_lines;
  while (in.next(tok, line)) {
    const std::string_view k = tok[0];
    if (k == "v") {
      if (tok.size() < 4) {
        return parse_fail(line, "vertex needs 3 coordinates, found " +
                                    std::to_string(tok.size() - 1));
      }
      const std::size_t v = mesh.vertex_count() + 1;
      for (int a = 0; a < 3; ++a) {
        double x = 0;
        Result<Mesh_buffers> r;
        if (!read_coordinate(tok[1 + a], line,
                             std::string(axis_name[a]) +
                                 " coordinate of vertex " + std::to_string(v),
                             x, r)) {
          return r;
        }
        mesh.positions.push_back(x);
      }
      // w or a vertex colour: accepted, not kept.
      for (std::size_t i = 4; i < tok.size(); ++i) {
        double x = 0;
        if (parse_double(tok[i], x) == Number::not_number) {
          return parse_fail(line, "value " + std::to_string(i) + " of vertex " +
                                      std::to_string(v) +
                                      " is not a number: " + quoted(tok[i]));
        }
      }
    } else if (k == "f") {
      const long long defined = static_cast<long long>(mesh.vertex_count());
      for (std::size_t i = 1; i < tok.size(); ++i) {
        long long v = 0;
        if (!parse_obj_corner(tok[i], v)) {
          return parse_fail(
              line,
              quoted(tok[i]) +
                  " is not a face vertex (expected v, v/vt, v//vn or v/vt/vn)");
        }
        long long index = 0;  // 0-based
        if (v == 0) {
          Result<Mesh_buffers> r;
          r.status = Status::error(
              Status_code::invalid_mesh,
              at(line) +
                  "face index 0 is out of range (OBJ indices start at 1)",
              line);
          return r;
        }
        if (v < 0) {
          index = defined + v;
          if (index < 0) {
            Result<Mesh_buffers> r;
            r.status = Status::error(
                Status_code::invalid_mesh,
                at(line) + "relative face index " +
                    std::string(tok[i].substr(0, tok[i].find('/'))) +
                    " is out of range (" + std::to_string(defined) +
                    " vertices defined so far)",
                line);
            return r;
          }
        } else {
          // Positive indices may refer to vertices defined further down;
          // check_buffers checks them against the final count.
          index = v - 1;
          if (index >= 0xffffffffll) {
            Result<Mesh_buffers> r;
            r.status = Status::error(
                Status_code::invalid_mesh,
                at(line) + "face index " +
                    std::string(tok[i].substr(0, tok[i].find('/'))) +
                    " is out of range (more than any mesh can hold)",
                line);
            return r;
          }
        }
        mesh.face_indices.push_back(static_cast<std::uint32_t>(index));
      }
      mesh.face_sizes.push_back(static_cast<std::uint32_t>(tok.size() - 1));
      face_lines.push_back(line);
    } else if (!is_ignored_obj_statement(k)) {
      return parse_fail(line, "unknown OBJ statement " + quoted(k));
    }
  }
  return finish(std::move(mesh), face_lines, 1);
}

// ---------------------------------------------------------------- writing

void append_number(std::string& out, double x) {
  char buf[32];
  const int n = std::snprintf(buf, sizeof buf, "%.17g", x);
  out.append(buf, static_cast<std::size_t>(n));
}

void append_uint(std::string& out, std::uint64_t x) {
  char buf[24];
  const int n = std::snprintf(buf, sizeof buf, "%llu",
                              static_cast<unsigned long long>(x));
  out.append(buf, static_cast<std::size_t>(n));
}

}  // namespace

Result<Mesh_buffers> read_mesh(std::string_view text, Mesh_format format) {
  try {
    return format == Mesh_format::off ? read_off(text) : read_obj(text);
  } catch (const std::bad_alloc&) {
    Result<Mesh_buffers> r;
    r.status = Status::error(Status_code::too_large,
                             "out of memory while reading the mesh");
    return r;
  } catch (const std::exception& e) {
    Result<Mesh_buffers> r;
    r.status = Status::error(
        Status_code::internal_error,
        std::string("unexpected failure while reading the mesh: ") + e.what());
    return r;
  }
}

Status check_writable(const Mesh_buffers& mesh) {
  if (mesh.positions.size() % 3 != 0)
    return Status::error(Status_code::invalid_mesh,
                         "positions hold " +
                             std::to_string(mesh.positions.size()) +
                             " numbers, not a multiple of 3");
  for (std::size_t i = 0; i < mesh.positions.size(); ++i) {
    if (std::isfinite(mesh.positions[i])) continue;
    // "nan" or "inf" in the text would be refused when read back.
    return Status::error(
        Status_code::invalid_mesh,
        "vertex " + std::to_string(i / 3) + " has a non-finite coordinate");
  }
  std::uint64_t total = 0;
  for (const std::uint32_t k : mesh.face_sizes) total += k;
  if (total != mesh.face_indices.size())
    return Status::error(Status_code::invalid_mesh,
                         "face sizes add up to " + std::to_string(total) +
                             " indices but there are " +
                             std::to_string(mesh.face_indices.size()));
  const std::size_t nv = mesh.vertex_count();
  for (std::size_t i = 0; i < mesh.face_indices.size(); ++i) {
    if (mesh.face_indices[i] < nv) continue;
    return Status::error(
        Status_code::invalid_mesh,
        "vertex index " + std::to_string(mesh.face_indices[i]) +
            " is out of range (" + std::to_string(nv) + " vertices)");
  }
  return Status::success();
}

std::string write_mesh(const Mesh_buffers& mesh, Mesh_format format) {
  std::string out;
  const std::size_t nv = mesh.vertex_count(), nf = mesh.face_count();
  out.reserve(nv * 60 + mesh.face_indices.size() * 8 + nf * 4 + 32);
  const bool off = format == Mesh_format::off;
  if (off) {
    out += "OFF\n";
    append_uint(out, nv);
    out += ' ';
    append_uint(out, nf);
    out += " 0\n";
  }
  for (std::size_t v = 0; v < nv; ++v) {
    if (!off) out += "v ";
    for (int a = 0; a < 3; ++a) {
      if (a > 0) out += ' ';
      append_number(out, mesh.positions[3 * v + a]);
    }
    out += '\n';
  }
  std::size_t o = 0;
  for (std::size_t f = 0; f < nf; ++f) {
    const std::uint32_t k = mesh.face_sizes[f];
    if (off) {
      append_uint(out, k);
    } else {
      out += 'f';
    }
    for (std::uint32_t i = 0; i < k; ++i) {
      out += ' ';
      append_uint(out, std::uint64_t(mesh.face_indices[o + i]) + (off ? 0 : 1));
    }
    o += k;
    out += '\n';
  }
  return out;
}

}  // namespace subdivlab
