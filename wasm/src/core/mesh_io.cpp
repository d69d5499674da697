// OFF and OBJ text in and out.
//
// Both readers are line based: every error names the 1-based line it was
// found on, and a header's counts are trusted only as far as the text backs
// them (reserve never exceeds what the remaining bytes could hold). After
// parsing, the buffers go through the same checks as build_mesh
// (detail::check_buffers) with faces named by their lines, and isolated
// vertices are dropped as build_mesh drops them.
//
// Speed: each data line is first read by a fast path that walks its bytes
// once (numbers by fast_float, indices by a digit loop) and accepts only the
// common, valid shapes of a line. Anything else - signs on indices, colours
// it does not expect, a bad token, a short line - is read again by the
// general path (the line split into tokens), which either accepts it or says
// what is wrong. The general path is the reference; the fast path must give
// the same values whenever it accepts a line.

#include "mesh_io.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <functional>
#include <limits>
#include <new>
#include <string>
#include <string_view>
#include <system_error>
#include <unordered_map>
#include <vector>

// Correctly rounded decimal -> double (Debian's libfast-float-dev, header
// only): strtod's results at a fraction of its cost, and em++ 3.1.6's libc++
// has no floating-point std::from_chars.
#include <fast_float/fast_float.h>

#include "file_kind.h"
#include "mesh_check.h"
#include "orientation_repair.h"
#include "parse_failure.h"
#include "ply_io.h"
#include "stl_io.h"
#include "text_writer.h"

namespace subdivlab {
namespace {

// ---------------------------------------------------------------- lexing

/// Yields the lines of a text: "\n", "\r\n" and lone "\r" end a line, a
/// leading UTF-8 byte order mark is skipped, and a '#' starts a comment.
/// Two ways to read a line: next() splits it into tokens; data_line() only
/// finds it, for a fast path that reads its bytes from cursor() and ends it
/// with end_line(), or gives up and takes the tokens with take_line().
class Line_reader {
 public:
  explicit Line_reader(std::string_view text)
      : text_(text), begin_(text.data()), end_(text.data() + text.size()) {
    if (text_.substr(0, 3) == "\xEF\xBB\xBF") pos_ = 3;
  }

  /// Next line that holds anything but blanks and comments; false at the
  /// end. `line` is its 1-based number.
  bool next(std::vector<std::string_view>& tokens, int& line) {
    if (!data_line(line)) return false;
    take_line(tokens);
    return true;
  }

  /// Finds the next line that holds anything but blanks and comments
  /// (false at the end); cursor() is then its first non-blank byte. The line
  /// must be finished with end_line() or take_line().
  bool data_line(int& line) {
    while (pos_ < text_.size()) {
      const char* p = begin_ + pos_;
      const char* q = skip_blanks(p);
      ++line_;
      if (q == end_ || *q == '\n' || *q == '\r' || *q == '#') {
        if (tag_comments_ && q != end_ && *q == '#' && is_tag_comment(q + 1)) {
          // The line is read from after its '#': "t NAME counts ...".
          line_begin_ = q + 1;
          cursor_ = skip_blanks(q + 1);
          line = line_;
          return true;
        }
        pos_ = after_line(q);
        continue;
      }
      line_begin_ = p;
      cursor_ = q;
      line = line_;
      return true;
    }
    return false;
  }

  const char* cursor() const { return cursor_; }
  const char* text_end() const { return end_; }

  /// From now on a comment "# t ..." is a line of its own (OFF's tags, the
  /// OBJ tag syntax after "# "); other comments stay comments.
  void read_tag_comments() { tag_comments_ = true; }
  /// Whether the current line is such a comment: it is read from after a
  /// '#', where any other line starts at a line's beginning (found without
  /// a flag to set on every line of the fast path).
  bool at_tag_comment() const {
    return line_begin_ != begin_ && line_begin_[-1] == '#';
  }

  /// Ends the current line at `p` if only blanks and a comment follow;
  /// false (nothing consumed) otherwise.
  bool end_line(const char* p) {
    p = skip_blanks(p);
    if (p != end_ && *p != '\n' && *p != '\r' && *p != '#') return false;
    pos_ = after_line(p);
    return true;
  }

  /// The current line's tokens (from its start, whatever a fast path read);
  /// ends the line, and with read_continuations() the lines it continues
  /// into (continued_lines() says how many).
  void take_line(std::vector<std::string_view>& tokens) {
    tokens.clear();
    continued_ = 0;
    const char* b = line_begin_;
    for (;;) {
      const char* e = b;
      while (e != end_ && *e != '\n' && *e != '\r') ++e;
      std::string_view content(b, static_cast<std::size_t>(e - b));
      const std::size_t hash = content.find('#');
      if (hash != std::string_view::npos) content = content.substr(0, hash);
      const bool more = continuations_ && ends_in_backslash(content);
      split(content, tokens);
      pos_ = after_line(e);
      // A backslash on the file's last line continues into nothing.
      if (!more || pos_ == text_.size()) return;
      ++line_;
      ++continued_;
      b = begin_ + pos_;
    }
  }

  /// From now on a backslash at the end of a line's data (blanks and a
  /// comment may follow it) joins the next line to it, as OBJ has it; the
  /// backslash separates tokens as a blank does. The fast paths need not
  /// know: a backslash is neither a number, an index nor a token's end, so
  /// they decline such a line and take_line reads it.
  void read_continuations() { continuations_ = true; }
  /// How many lines after its first the statement take_line read last
  /// continued into.
  int continued_lines() const { return continued_; }

  /// Number of the last line of the text (where "the file ends").
  int last_line() const { return line_ == 0 ? 1 : line_; }

  /// Bytes not read yet; bounds what any declared count may reserve.
  std::size_t remaining() const { return text_.size() - pos_; }

  static bool is_blank(char c) {
    return c == ' ' || c == '\t' || c == '\v' || c == '\f';
  }
  /// Whether a token ends before `p`: a blank, the line's end or a comment.
  bool token_ends(const char* p) const {
    return p == end_ || is_blank(*p) || *p == '\n' || *p == '\r' || *p == '#';
  }
  const char* skip_blanks(const char* p) const {
    while (p != end_ && is_blank(*p)) ++p;
    return p;
  }

 private:
  /// Whether a comment's text from `p` (after its '#') is a tag: blanks,
  /// then "t" as a token of its own.
  bool is_tag_comment(const char* p) const {
    p = skip_blanks(p);
    return p != end_ && *p == 't' && token_ends(p + 1);
  }
  /// Offset of the line after the one `p` is in (past its terminator).
  std::size_t after_line(const char* p) const {
    while (p != end_ && *p != '\n' && *p != '\r') ++p;
    if (p != end_) p += (*p == '\r' && p + 1 != end_ && p[1] == '\n') ? 2 : 1;
    return static_cast<std::size_t>(p - begin_);
  }
  /// Whether `s` ends in a backslash and blanks; if so, drops them.
  static bool ends_in_backslash(std::string_view& s) {
    std::size_t n = s.size();
    while (n > 0 && is_blank(s[n - 1])) --n;
    if (n == 0 || s[n - 1] != '\\') return false;
    s = s.substr(0, n - 1);
    return true;
  }
  /// Appends the blank-separated tokens of `s`.
  static void split(std::string_view s, std::vector<std::string_view>& tokens) {
    std::size_t i = 0;
    while (i < s.size()) {
      while (i < s.size() && is_blank(s[i])) ++i;
      const std::size_t b = i;
      while (i < s.size() && !is_blank(s[i])) ++i;
      if (i > b) tokens.push_back(s.substr(b, i - b));
    }
  }

  std::string_view text_;
  const char* begin_;
  const char* end_;
  std::size_t pos_ = 0;
  int line_ = 0;
  const char* line_begin_ = nullptr;
  const char* cursor_ = nullptr;
  bool tag_comments_ = false;
  bool continuations_ = false;
  int continued_ = 0;
};

enum class Number { ok, not_number, not_finite };

/// fast_float on [p, end) after an optional '+' (which it does not take);
/// where the number ends, or nullptr. A value beyond the double range
/// comes back infinite.
const char* scan_double(const char* p, const char* end, double& out) {
  if (p != end && *p == '+') {
    ++p;
    if (p != end && (*p == '+' || *p == '-')) return nullptr;
  }
  const fast_float::from_chars_result r = fast_float::from_chars(p, end, out);
  if (r.ec == std::errc::result_out_of_range) {
    out = std::numeric_limits<double>::infinity();
    return r.ptr;
  }
  return r.ec == std::errc() ? r.ptr : nullptr;
}

/// Whether `tok` spells inf, infinity, nan or nan(...), any case, signed.
bool is_inf_or_nan(std::string_view tok) {
  if (!tok.empty() && (tok[0] == '+' || tok[0] == '-')) tok.remove_prefix(1);
  const auto lower_is = [&tok](std::string_view word) {
    if (tok.size() < word.size()) return false;
    for (std::size_t i = 0; i < word.size(); ++i) {
      const auto c = static_cast<unsigned char>(tok[i]);
      if (std::tolower(c) != word[i]) return false;
    }
    return true;
  };
  if (tok.size() == 3 && (lower_is("inf") || lower_is("nan"))) return true;
  if (tok.size() == 8 && lower_is("infinity")) return true;
  return lower_is("nan(");
}

/// Strict decimal floating point: the whole token must be a number such as
/// "1", "-0.5", "1e5" or ".5". "inf"/"nan" and values beyond the double
/// range are non-finite; hex floats, "1.2.3" and "abc" are not numbers.
Number parse_double(std::string_view tok, double& out) {
  if (tok.empty() || tok.size() > 400) return Number::not_number;
  if (is_inf_or_nan(tok)) return Number::not_finite;
  for (char c : tok) {
    const bool ok = (c >= '0' && c <= '9') || c == '.' || c == 'e' ||
                    c == 'E' || c == '+' || c == '-';
    if (!ok) return Number::not_number;
  }
  double v = 0;
  const char* end = tok.data() + tok.size();
  if (scan_double(tok.data(), end, v) != end) return Number::not_number;
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

// ------------------------------------------------------- fast path

/// A number as parse_double reads it, found at `p`: a finite value whose
/// token ends where the number does. nullptr for anything else (the line is
/// then read again by the general path).
const char* fast_number(const Line_reader& in, const char* p, double& out) {
  const char* e = scan_double(p, in.text_end(), out);
  if (e == nullptr || e - p > 400 || !in.token_ends(e) || !std::isfinite(out))
    return nullptr;
  return e;
}

/// Unsigned digits at `p` (at most 10, no sign); where they end or nullptr.
/// Inlined by force: em++ left it a call per index (6% of OFF's parse).
[[gnu::always_inline]] inline const char* scan_digits(const char* p,
                                                      const char* end,
                                                      std::uint64_t& out) {
  const char* const start = p;
  std::uint64_t v = 0;
  while (p != end && static_cast<unsigned char>(*p - '0') < 10) {
    v = v * 10 + static_cast<unsigned>(*p - '0');
    if (++p - start > 10) return nullptr;
  }
  if (p == start) return nullptr;
  out = v;
  return p;
}

/// After the values a line must have: up to `max_extra` more finite numbers
/// (0 for no limit), then the end of the line. Ends the line; false
/// (nothing consumed) when something else follows.
bool fast_extras(Line_reader& in, const char* p, std::size_t max_extra,
                 std::size_t& extra) {
  extra = 0;
  for (;;) {
    const char* q = in.skip_blanks(p);
    if (in.token_ends(q)) break;
    if (max_extra != 0 && extra == max_extra) return false;
    double x = 0;
    p = fast_number(in, q, x);
    if (p == nullptr) return false;
    ++extra;
  }
  return in.end_line(p);
}

/// An OFF or OBJ vertex line's x y z at `p`, then at least `min_extra`
/// further numbers; appends x y z and ends the line, or returns false.
bool fast_vertex(Line_reader& in, const char* p, std::size_t min_extra,
                 std::vector<double>& positions) {
  double x[3];
  for (int a = 0; a < 3; ++a) {
    p = fast_number(in, in.skip_blanks(p), x[a]);
    if (p == nullptr) return false;
  }
  std::size_t extra = 0;
  if (!fast_extras(in, p, 0, extra) || extra < min_extra) return false;
  positions.insert(positions.end(), x, x + 3);
  return true;
}

/// An OFF face line "k i1 .. ik [colour]" with plain indices below `nv`;
/// appends the indices and returns k, or returns -1 (nothing appended, the
/// line not ended).
long long fast_off_face(Line_reader& in, std::size_t nv,
                        std::vector<std::uint32_t>& indices) {
  const char* const end = in.text_end();
  std::uint64_t k = 0;
  const char* p = scan_digits(in.cursor(), end, k);
  if (p == nullptr || !in.token_ends(p)) return -1;
  const std::size_t start = indices.size();
  for (std::uint64_t i = 0; i < k; ++i) {
    std::uint64_t v = 0;
    const char* e = scan_digits(in.skip_blanks(p), end, v);
    if (e == nullptr || !in.token_ends(e) || v >= nv) {
      indices.resize(start);
      return -1;
    }
    indices.push_back(static_cast<std::uint32_t>(v));
    p = e;
  }
  std::size_t extra = 0;
  if (!fast_extras(in, p, 4, extra)) {
    indices.resize(start);
    return -1;
  }
  return static_cast<long long>(k);
}

/// An OBJ face line's corners after "f" at `p`, each a positive v, v/vt,
/// v//vn or v/vt/vn without signs; appends v - 1 for each and returns the
/// count, or -1 (nothing appended, the line not ended).
long long fast_obj_face(Line_reader& in, const char* p,
                        std::vector<std::uint32_t>& indices) {
  const char* const end = in.text_end();
  const std::size_t start = indices.size();
  const auto fail = [&] {
    indices.resize(start);
    return -1;
  };
  long long corners = 0;
  for (;;) {
    p = in.skip_blanks(p);
    if (in.token_ends(p)) break;
    std::uint64_t v = 0, unused = 0;
    p = scan_digits(p, end, v);
    if (p == nullptr || v == 0 || v - 1 >= 0xffffffffull) return fail();
    if (p != end && *p == '/') {
      const char* vt = scan_digits(p + 1, end, unused);
      const char* q = vt != nullptr ? vt : p + 1;
      if (q != end && *q == '/') {
        p = scan_digits(q + 1, end, unused);  // v//vn or v/vt/vn
      } else {
        p = vt;  // v/vt
      }
      if (p == nullptr) return fail();
    }
    if (!in.token_ends(p)) return fail();
    indices.push_back(static_cast<std::uint32_t>(v - 1));
    ++corners;
  }
  if (!in.end_line(p)) return fail();
  return corners;
}

// Runs: the fast path over many lines in one call. Each run is out of line
// and holds nothing with a destructor, so it needs no landing pad. That
// matters in WebAssembly: with Emscripten's JavaScript exceptions, every
// call made where a landing pad is live (read_mesh's try block, a function
// with a string or vector local) goes through a JavaScript invoke_* wrapper,
// and with the fast path inlined into read_mesh those round trips cost OFF
// about half its parse time. Inside a run the calls are plain; an exception
// (bad_alloc from a growing vector) passes through to read_mesh's handler.

/// Where a run stopped.
enum class Run_stop {
  count,      ///< every line asked for was read
  slow_line,  ///< at a data line the fast path declines: found, not read
  text_end,   ///< the text ended first
};

/// Up to `count` OFF vertex lines by the fast path (x y z and at least
/// `min_extra` more numbers); returns how many it read. Without `fast` it
/// declines every line (the general path alone, for the tests).
[[gnu::noinline]] std::size_t fast_off_vertex_run(
    Line_reader& in, bool fast, std::size_t count, std::size_t min_extra,
    std::vector<double>& positions, int& line, Run_stop& stop) {
  for (std::size_t v = 0; v < count; ++v) {
    if (!in.data_line(line)) {
      stop = Run_stop::text_end;
      return v;
    }
    if (!fast || !fast_vertex(in, in.cursor(), min_extra, positions)) {
      stop = Run_stop::slow_line;
      return v;
    }
  }
  stop = Run_stop::count;
  return count;
}

/// Up to `count` OFF face lines by the fast path (indices below `nv`), each
/// face's line appended to `face_lines`; returns how many it read.
/// Without `fast` it declines every line.
[[gnu::noinline]] std::size_t fast_off_face_run(Line_reader& in, bool fast,
                                                std::size_t count,
                                                std::size_t nv,
                                                Mesh_buffers& mesh,
                                                std::vector<int>& face_lines,
                                                int& line, Run_stop& stop) {
  for (std::size_t f = 0; f < count; ++f) {
    if (!in.data_line(line)) {
      stop = Run_stop::text_end;
      return f;
    }
    const long long k = fast ? fast_off_face(in, nv, mesh.face_indices) : -1;
    if (k < 0) {
      stop = Run_stop::slow_line;
      return f;
    }
    mesh.face_sizes.push_back(static_cast<std::uint32_t>(k));
    face_lines.push_back(line);
  }
  stop = Run_stop::count;
  return count;
}

/// OBJ "v" and "f" lines by the fast path until a data line it declines
/// (slow_line) or the end of the text (text_end). Without `fast` it
/// declines every line.
[[gnu::noinline]] Run_stop fast_obj_run(Line_reader& in, bool fast,
                                        Mesh_buffers& mesh,
                                        std::vector<int>& face_lines,
                                        int& line) {
  while (in.data_line(line)) {
    const char* c = in.cursor();
    if (!fast || c + 1 == in.text_end() || !Line_reader::is_blank(c[1]))
      return Run_stop::slow_line;
    if (*c == 'v') {
      if (!fast_vertex(in, c + 1, 0, mesh.positions))
        return Run_stop::slow_line;
    } else if (*c == 'f') {
      const long long corners = fast_obj_face(in, c + 1, mesh.face_indices);
      if (corners < 0) return Run_stop::slow_line;
      mesh.face_sizes.push_back(static_cast<std::uint32_t>(corners));
      face_lines.push_back(line);
    } else {
      return Run_stop::slow_line;
    }
  }
  return Run_stop::text_end;
}

std::string at(int line) { return "line " + std::to_string(line) + ": "; }
using detail::quoted;

using detail::parse_failure;

/// Reads one coordinate; on failure fills `r` with the reason.
bool read_coordinate(std::string_view tok, int line, const std::string& what,
                     double& out, Result<Mesh_buffers>& r) {
  switch (parse_double(tok, out)) {
    case Number::ok:
      return true;
    case Number::not_finite:
      r = parse_failure(line, what + " is not finite: " + quoted(tok));
      return false;
    case Number::not_number:
      r = parse_failure(line, what + " is not a number: " + quoted(tok));
      return false;
  }
  return false;
}

const char* const axis_name[3] = {"x", "y", "z"};

// ---------------------------------------------------------------- tags
//
// OpenSubdiv's tag lines (regression/common/shape_utils.cpp's parseTag,
// far_utils.h's use of them): "t NAME nint/nfloat/nstring" and then that
// many integers, floats and strings. Indices in tags count from 0, in OBJ
// as in OFF (unlike OBJ's "f" lines). A line is checked for its own syntax
// when it is read; what needs the whole mesh (indices against the vertex
// and face counts, crease pairs against the edges) is checked by
// apply_tags once the file is read, still naming the tag's line.

enum class Tag_kind { crease, corner, hole, boundary, crease_method };

/// A tag line whose own syntax is checked.
struct Tag_line {
  int line = 0;
  Tag_kind kind = Tag_kind::crease;
  /// Vertices (crease: in pairs; corner) or faces (hole), as in the file.
  std::vector<long long> indices;
  /// One for all the edges or vertices, or one each.
  std::vector<float> sharpness;
  Boundary_interpolation boundary = Boundary_interpolation::edge_only;
  Crease_method crease_method = Crease_method::uniform;
};

/// The tags of a file in line order, and the notes on those not applied.
struct Tag_list {
  std::vector<Tag_line> lines;
  std::vector<std::string> notes;
  /// Tags not applied, noted or not: a note each for the first
  /// max_unapplied_notes, then one line for the rest (a file of a million
  /// such lines must not become a million messages).
  std::size_t unapplied = 0;
};

constexpr std::size_t max_unapplied_notes = 100;

std::string plural(std::size_t n, const char* one, const char* many) {
  return std::to_string(n) + " " + (n == 1 ? one : many);
}

/// "a/b/c" of three non-negative decimal integers (saturating as parse_int
/// does: a huge count then fails the count of values).
bool parse_tag_counts(std::string_view tok, unsigned long long n[3]) {
  for (int i = 0; i < 3; ++i) {
    const std::size_t slash = tok.find('/');
    if ((i < 2) != (slash != std::string_view::npos)) return false;
    const std::string_view part = tok.substr(0, slash);
    if (part.empty()) return false;
    for (const char c : part)
      if (c < '0' || c > '9') return false;
    long long v = 0;
    parse_int(part, v);
    n[i] = static_cast<unsigned long long>(v);
    if (i < 2) tok.remove_prefix(slash + 1);
  }
  return true;
}

/// One sharpness value: a finite number, 0 or more, that a float holds.
bool read_sharpness(std::string_view tok, int line, const std::string& tag,
                    float& out, Result<Mesh_buffers>& r) {
  double v = 0;
  const Number n = parse_double(tok, v);
  std::string problem;
  if (n == Number::not_number) {
    problem = "is not a number";
  } else if (n == Number::not_finite) {
    problem = "is not finite";
  } else if (v < 0) {
    problem = "is negative (0 is smooth, 10 and more infinitely sharp)";
  } else if (v > std::numeric_limits<float>::max()) {
    problem = "is too large for a float (10 and more is infinitely sharp)";
  } else {
    out = static_cast<float>(v);
    return true;
  }
  r = parse_failure(line, tag + ": sharpness " + quoted(tok) + " " + problem);
  return false;
}

/// Reads the tag line `tok` ("t", NAME, counts, values) into `tags`, or
/// fills `r` with what is wrong with it.
bool read_tag(const std::vector<std::string_view>& tok, int line,
              Tag_list& tags, Result<Mesh_buffers>& r) {
  const auto fail = [&](const std::string& what) {
    r = parse_failure(line, what);
    return false;
  };
  if (tok.size() < 3) {
    return fail(
        "a tag needs a name and its counts: t NAME nint/nfloat/nstring "
        "values...");
  }
  const std::string_view name = tok[1], counts = tok[2];
  const std::string tag = "tag " + quoted(name);
  unsigned long long n[3] = {0, 0, 0};
  if (!parse_tag_counts(counts, n)) {
    return fail(tag + " counts " + quoted(counts) +
                " are not nint/nfloat/nstring (three integers 0 or more, as "
                "in 2/1/0)");
  }
  const std::size_t given = tok.size() - 3;
  if (n[0] + n[1] + n[2] != given) {
    return fail(tag + " needs " + std::to_string(n[0] + n[1] + n[2]) +
                " values after its counts " + quoted(counts) + ", found " +
                std::to_string(given));
  }
  const std::size_t ni = n[0], nf = n[1], ns = n[2];
  const std::string_view* ints = tok.data() + 3;
  const std::string_view* floats = ints + ni;
  const std::string_view* strings = floats + nf;

  Tag_line t;
  t.line = line;
  if (name == "crease") {
    t.kind = Tag_kind::crease;
  } else if (name == "corner") {
    t.kind = Tag_kind::corner;
  } else if (name == "hole") {
    t.kind = Tag_kind::hole;
  } else if (name == "interpolateboundary") {
    t.kind = Tag_kind::boundary;
  } else if (name == "creasemethod") {
    t.kind = Tag_kind::crease_method;
  } else {
    // Well formed, not applied (facevaryinginterpolateboundary,
    // smoothtriangles ...): its values must still be what the counts say.
    for (std::size_t i = 0; i < ni; ++i) {
      long long v = 0;
      if (!parse_int(ints[i], v))
        return fail(tag + ": " + quoted(ints[i]) + " is not an integer");
    }
    for (std::size_t i = 0; i < nf; ++i) {
      double v = 0;
      if (parse_double(floats[i], v) == Number::not_number)
        return fail(tag + ": " + quoted(floats[i]) + " is not a number");
    }
    if (tags.unapplied++ < max_unapplied_notes)
      tags.notes.push_back(at(line) + tag + " is not applied");
    return true;
  }

  if (t.kind == Tag_kind::boundary) {
    if (ni != 1 || nf != 0 || ns != 0) {
      return fail(tag + " needs the counts 1/0/0 (one integer), found " +
                  quoted(counts));
    }
    long long v = -1;
    if (!parse_int(ints[0], v) || v < 0 || v > 2) {
      return fail(tag + ": " + quoted(ints[0]) +
                  " is not 0 (none), 1 (edge and corner) or 2 (edge only)");
    }
    t.boundary = v == 0   ? Boundary_interpolation::none
                 : v == 1 ? Boundary_interpolation::edge_and_corner
                          : Boundary_interpolation::edge_only;
    tags.lines.push_back(std::move(t));
    return true;
  }
  if (t.kind == Tag_kind::crease_method) {
    if (ni != 0 || nf != 0 || ns != 1) {
      return fail(tag + " needs the counts 0/0/1 (one string), found " +
                  quoted(counts));
    }
    if (strings[0] == "normal") {
      t.crease_method = Crease_method::uniform;
    } else if (strings[0] == "chaikin") {
      t.crease_method = Crease_method::chaikin;
    } else {
      return fail(tag + ": " + quoted(strings[0]) +
                  " is not normal or chaikin");
    }
    tags.lines.push_back(std::move(t));
    return true;
  }

  // crease, corner, hole: indices, and sharpness for the first two.
  if (ns != 0)
    return fail(tag + " takes no strings, found " + std::to_string(ns));
  const bool faces = t.kind == Tag_kind::hole;
  if (faces && nf != 0) {
    return fail(tag + " takes face indices only (counts N/0/0), found " +
                quoted(counts));
  }
  if (t.kind == Tag_kind::crease && ni % 2 != 0) {
    return fail(tag + " has " + plural(ni, "vertex", "vertices") +
                ": a crease's vertices come in pairs, one pair per edge");
  }
  if (!faces) {
    const std::size_t items = t.kind == Tag_kind::crease ? ni / 2 : ni;
    const char* item = t.kind == Tag_kind::crease ? "edge" : "vertex";
    if (nf != 1 && nf != items) {
      return fail(tag + " has " +
                  plural(nf, "sharpness value", "sharpness values") + " for " +
                  plural(items, item,
                         t.kind == Tag_kind::crease ? "edges" : "vertices") +
                  " (give 1 for all or one per " + item + ")");
    }
  }
  t.indices.resize(ni);
  for (std::size_t i = 0; i < ni; ++i) {
    if (!parse_int(ints[i], t.indices[i])) {
      return fail(tag + ": " + (faces ? "face" : "vertex") + " index " +
                  quoted(ints[i]) + " is not an integer");
    }
    // parse_int saturates: such a value is quoted as the file has it.
    if (t.indices[i] > 0xffffffffll || t.indices[i] < -0xffffffffll) {
      return fail(tag + ": " + (faces ? "face " : "vertex ") + quoted(ints[i]) +
                  " is out of range (more than any mesh can hold)");
    }
  }
  t.sharpness.resize(nf);
  for (std::size_t i = 0; i < nf; ++i) {
    if (!read_sharpness(floats[i], line, tag, t.sharpness[i], r)) return false;
  }
  tags.lines.push_back(std::move(t));
  return true;
}

/// Checks the tags against the mesh that `check_buffers` has accepted (its
/// vertex and face numbers as the file gave them, before isolated vertices
/// go) and stores them in mesh.tags: a repeated edge or vertex keeps its
/// first place and takes its last value, sharpness 0 (smooth) is dropped,
/// holes are sorted. False, with `r` naming the tag's line, on an index out
/// of range or a crease pair that is not an edge.
bool apply_tags(Tag_list&& tags, Mesh_buffers& mesh, Result<Mesh_buffers>& r) {
  Mesh_tags& out = mesh.tags;
  out.notes = std::move(tags.notes);
  if (tags.unapplied > max_unapplied_notes) {
    out.notes.push_back("and " +
                        std::to_string(tags.unapplied - max_unapplied_notes) +
                        " more tags that are not applied");
  }
  if (tags.lines.empty()) return true;
  const std::size_t nv = mesh.vertex_count(), nf = mesh.face_count();
  const auto key = [](std::uint64_t a, std::uint64_t b) {
    return a < b ? a << 32 | b : b << 32 | a;
  };
  std::vector<std::uint64_t> edges;  // sorted, built for the first crease
  std::unordered_map<std::uint64_t, std::size_t> crease_at;
  std::unordered_map<std::uint32_t, std::size_t> corner_at;
  std::vector<int> corner_line;  // the line that last set each corner
  for (const Tag_line& t : tags.lines) {
    const std::string tag = t.kind == Tag_kind::crease   ? "tag 'crease'"
                            : t.kind == Tag_kind::corner ? "tag 'corner'"
                                                         : "tag 'hole'";
    const std::size_t limit = t.kind == Tag_kind::hole ? nf : nv;
    for (const long long i : t.indices) {
      if (i >= 0 && static_cast<unsigned long long>(i) < limit) continue;
      r = parse_failure(
          t.line,
          tag + ": " + (t.kind == Tag_kind::hole ? "face " : "vertex ") +
              std::to_string(i) + " is out of range (" +
              plural(limit, t.kind == Tag_kind::hole ? "face" : "vertex",
                     t.kind == Tag_kind::hole ? "faces" : "vertices") +
              "; tag indices start at 0)");
      return false;
    }
    switch (t.kind) {
      case Tag_kind::boundary:
        out.boundary = t.boundary;
        out.boundary_given = true;
        break;
      case Tag_kind::crease_method:
        out.crease_method = t.crease_method;
        out.crease_method_given = true;
        break;
      case Tag_kind::hole:
        for (const long long f : t.indices)
          out.holes.push_back(static_cast<std::uint32_t>(f));
        break;
      case Tag_kind::crease:
        if (edges.empty()) {
          edges.reserve(mesh.face_indices.size());
          std::size_t o = 0;
          for (const std::uint32_t k : mesh.face_sizes) {
            for (std::uint32_t c = 0; c < k; ++c)
              edges.push_back(key(mesh.face_indices[o + c],
                                  mesh.face_indices[o + (c + 1) % k]));
            o += k;
          }
          std::sort(edges.begin(), edges.end());
        }
        for (std::size_t j = 0; j + 1 < t.indices.size(); j += 2) {
          const auto a = static_cast<std::uint32_t>(t.indices[j]);
          const auto b = static_cast<std::uint32_t>(t.indices[j + 1]);
          const std::uint64_t e = key(a, b);
          if (!std::binary_search(edges.begin(), edges.end(), e)) {
            r = parse_failure(t.line, tag + ": vertices " + std::to_string(a) +
                                          " and " + std::to_string(b) +
                                          " are not joined by an edge of the "
                                          "mesh");
            return false;
          }
          const float s =
              t.sharpness.size() == 1 ? t.sharpness[0] : t.sharpness[j / 2];
          const auto found = crease_at.emplace(e, out.crease_sharpness.size());
          if (found.second) {
            out.crease_edges.push_back(a);
            out.crease_edges.push_back(b);
            out.crease_sharpness.push_back(s);
          } else {
            out.crease_sharpness[found.first->second] = s;
          }
        }
        break;
      case Tag_kind::corner:
        for (std::size_t j = 0; j < t.indices.size(); ++j) {
          const auto v = static_cast<std::uint32_t>(t.indices[j]);
          const float s =
              t.sharpness.size() == 1 ? t.sharpness[0] : t.sharpness[j];
          const auto found = corner_at.emplace(v, out.corner_sharpness.size());
          if (found.second) {
            out.corner_vertices.push_back(v);
            out.corner_sharpness.push_back(s);
            corner_line.push_back(t.line);
          } else {
            out.corner_sharpness[found.first->second] = s;
            corner_line[found.first->second] = t.line;
          }
        }
        break;
    }
  }
  // Sharpness 0 is smooth: nothing to keep.
  std::size_t kept = 0;
  for (std::size_t i = 0; i < out.crease_sharpness.size(); ++i) {
    if (out.crease_sharpness[i] == 0) continue;
    out.crease_edges[2 * kept] = out.crease_edges[2 * i];
    out.crease_edges[2 * kept + 1] = out.crease_edges[2 * i + 1];
    out.crease_sharpness[kept++] = out.crease_sharpness[i];
  }
  out.crease_edges.resize(2 * kept);
  out.crease_sharpness.resize(kept);
  // A corner on a vertex no face uses goes with the vertex (as
  // drop_isolated_vertices drops it); the user is told.
  std::vector<bool> used;
  if (!out.corner_vertices.empty()) {
    used.assign(nv, false);
    for (const std::uint32_t v : mesh.face_indices) used[v] = true;
  }
  kept = 0;
  for (std::size_t i = 0; i < out.corner_sharpness.size(); ++i) {
    if (out.corner_sharpness[i] == 0) continue;
    if (!used[out.corner_vertices[i]]) {
      out.notes.push_back(at(corner_line[i]) + "tag 'corner': vertex " +
                          std::to_string(out.corner_vertices[i]) +
                          " is used by no face; it and its corner are dropped");
      continue;
    }
    out.corner_vertices[kept] = out.corner_vertices[i];
    out.corner_sharpness[kept++] = out.corner_sharpness[i];
  }
  out.corner_vertices.resize(kept);
  out.corner_sharpness.resize(kept);
  std::sort(out.holes.begin(), out.holes.end());
  out.holes.erase(std::unique(out.holes.begin(), out.holes.end()),
                  out.holes.end());
  return true;
}

/// The checks build_mesh makes, with faces named by their lines; then the
/// tags are checked against the mesh and kept, and the isolated vertices go
/// (the corners' halfedges stay as they are).
Result<Mesh_buffers> finish(Mesh_buffers&& mesh,
                            const std::vector<int>& face_lines,
                            std::uint32_t vertex_offset,
                            std::vector<std::uint32_t>* corner_halfedges,
                            Tag_list&& tags, const Read_options& options) {
  detail::Check_naming naming;
  naming.face_lines = &face_lines;
  naming.vertex_offset = vertex_offset;
  Result<Mesh_buffers> r;
  std::size_t reversed = 0;
  detail::Check_result check = detail::check_orientation(
      mesh, naming, corner_halfedges, options.repair_orientation, reversed);
  if (!check.status.ok()) {
    // inconsistent_orientation offers a repair: a tag the file holds wrong
    // (the tags do not depend on the faces' orientation) would fail the
    // repaired read, so it is named first.
    if (check.status.code == Status_code::inconsistent_orientation &&
        !apply_tags(std::move(tags), mesh, r))
      return r;
    r = Result<Mesh_buffers>{};
    r.status = std::move(check.status);
    return r;
  }
  if (!apply_tags(std::move(tags), mesh, r)) return r;
  if (reversed > 0) mesh.tags.notes.push_back(detail::reversed_note(reversed));
  r.value = detail::drop_isolated_vertices(std::move(mesh));
  return r;
}

// ---------------------------------------------------------------- OFF

Result<Mesh_buffers> read_off(std::string_view text,
                              std::vector<std::uint32_t>* corner_halfedges,
                              const Read_options& options, bool fast) {
  Line_reader in(text);
  std::vector<std::string_view> tok;
  int line = 0;
  if (!in.next(tok, line))
    return parse_failure(0, "the file is empty: no OFF header");

  // Header keyword: [ST][C][N][4][n]OFF, optionally followed by the counts.
  std::string_view key = tok[0];
  bool normals = false, colours = false, texture = false;
  {
    std::string_view k = key;
    if (k.substr(0, 2) == "ST") texture = true, k.remove_prefix(2);
    if (k.substr(0, 1) == "C") colours = true, k.remove_prefix(1);
    if (k.substr(0, 1) == "N") normals = true, k.remove_prefix(1);
    if (k == "4OFF" || k == "4nOFF") {
      return parse_failure(line,
                           "4D OFF (" + std::string(key) +
                               ") is not supported: SubdivLab reads 3D meshes");
    }
    if (k == "nOFF") {
      return parse_failure(
          line, "nOFF (" + std::string(key) +
                    ", dimension given in the file) is not supported");
    }
    if (k != "OFF") {
      return parse_failure(
          line, "unknown OFF header " + quoted(key) +
                    " (expected OFF, COFF, NOFF, CNOFF, STOFF or another "
                    "[ST][C][N]OFF variant)");
    }
  }
  std::size_t c0 = 1;
  if (tok.size() > 1 && tok[1] == "BINARY") {
    return parse_failure(
        line, "binary OFF is not supported; save the mesh as text OFF");
  }
  if (tok.size() == 1) {
    if (!in.next(tok, line))
      return parse_failure(in.last_line(), "file ends before the counts line");
    c0 = 0;
  }
  const std::size_t n_counts = tok.size() - c0;
  if (n_counts < 2 || n_counts > 3) {
    return parse_failure(line,
                         "expected the counts 'vertices faces edges', found " +
                             std::to_string(n_counts) + " values");
  }
  long long nv_ll = 0, nf_ll = 0, ne_ll = 0;
  const char* count_name[3] = {"vertex", "face", "edge"};
  long long* count_val[3] = {&nv_ll, &nf_ll, &ne_ll};
  for (std::size_t i = 0; i < n_counts; ++i) {
    if (!parse_int(tok[c0 + i], *count_val[i]) || *count_val[i] < 0) {
      return parse_failure(line, std::string(count_name[i]) + " count " +
                                     quoted(tok[c0 + i]) +
                                     " is not a non-negative integer");
    }
  }
  if (nv_ll > 0xfffffffell)
    return parse_failure(
        line, "vertex count " + std::string(tok[c0]) + " is too large");
  if (nf_ll > 0xfffffffell)
    return parse_failure(
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
    Run_stop stop = Run_stop::count;
    v += fast_off_vertex_run(in, fast, nv - v, min_values - 3, mesh.positions,
                             line, stop);
    if (stop == Run_stop::count) break;
    if (stop == Run_stop::text_end) {
      return parse_failure(in.last_line(),
                           "file ends after " + std::to_string(v) + " of " +
                               std::to_string(nv) + " vertices");
    }
    in.take_line(tok);
    if (tok.size() < min_values) {
      std::string need = "x y z";
      if (normals) need += ", a normal";
      if (colours) need += ", a colour";
      if (texture) need += ", texture coordinates";
      return parse_failure(line, "vertex " + std::to_string(v) + " has " +
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
        return parse_failure(line, "value " + std::to_string(i + 1) +
                                       " of vertex " + std::to_string(v) +
                                       " is not a number: " + quoted(tok[i]));
      }
    }
  }

  for (std::size_t f = 0; f < nf; ++f) {
    Run_stop stop = Run_stop::count;
    f += fast_off_face_run(in, fast, nf - f, nv, mesh, face_lines, line, stop);
    if (stop == Run_stop::count) break;
    if (stop == Run_stop::text_end) {
      return parse_failure(in.last_line(), "file ends after " +
                                               std::to_string(f) + " of " +
                                               std::to_string(nf) + " faces");
    }
    in.take_line(tok);
    long long k = 0;
    if (!parse_int(tok[0], k) || k < 0) {
      return parse_failure(
          line, "face " + std::to_string(f) +
                    " must start with its vertex count, found " +
                    quoted(tok[0]) + " (do the header counts match the data?)");
    }
    const std::size_t listed = tok.size() - 1;
    if (static_cast<unsigned long long>(k) > listed) {
      return parse_failure(line, "face " + std::to_string(f) + " declares " +
                                     std::string(tok[0]) +
                                     " vertices but lists only " +
                                     std::to_string(listed));
    }
    const std::size_t extra = listed - static_cast<std::size_t>(k);
    if (extra > 4) {
      return parse_failure(
          line,
          "face " + std::to_string(f) + " declares " + std::string(tok[0]) +
              " vertices but the line has " + std::to_string(extra) +
              " more values (at most 4, a colour, may follow the indices)");
    }
    for (std::size_t i = 1; i <= static_cast<std::size_t>(k); ++i) {
      long long index = 0;
      if (!parse_int(tok[i], index)) {
        return parse_failure(
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
        return parse_failure(line, "colour value of face " + std::to_string(f) +
                                       " is not a number: " + quoted(tok[i]));
      }
    }
    mesh.face_sizes.push_back(static_cast<std::uint32_t>(k));
    face_lines.push_back(line);
  }
  // After the faces, comments "# t ..." are tags; any other data is not.
  Tag_list tags;
  in.read_tag_comments();
  while (in.next(tok, line)) {
    if (!in.at_tag_comment()) {
      return parse_failure(line,
                           "extra data after the " + std::to_string(nf) +
                               " faces the header declares (header counts "
                               "disagree with the data)");
    }
    Result<Mesh_buffers> r;
    if (!read_tag(tok, line, tags, r)) return r;
  }
  return finish(std::move(mesh), face_lines, 0, corner_halfedges,
                std::move(tags), options);
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

/// One OBJ statement the general path reads (its tokens `tok`, from line
/// `line`) into `mesh`, `face_lines` and `tags`; a failure names `line`.
Result<Mesh_buffers> read_obj_statement(
    const std::vector<std::string_view>& tok, int line, Mesh_buffers& mesh,
    std::vector<int>& face_lines, Tag_list& tags) {
  const std::string_view k = tok[0];
  if (k == "v") {
    if (tok.size() < 4) {
      return parse_failure(line, "vertex needs 3 coordinates, found " +
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
        return parse_failure(line, "value " + std::to_string(i) +
                                       " of vertex " + std::to_string(v) +
                                       " is not a number: " + quoted(tok[i]));
      }
    }
  } else if (k == "f") {
    const long long defined = static_cast<long long>(mesh.vertex_count());
    for (std::size_t i = 1; i < tok.size(); ++i) {
      long long v = 0;
      if (!parse_obj_corner(tok[i], v)) {
        return parse_failure(
            line,
            quoted(tok[i]) +
                " is not a face vertex (expected v, v/vt, v//vn or v/vt/vn)");
      }
      long long index = 0;  // 0-based
      if (v == 0) {
        // Named as the file spells it: "-0" is no relative index either.
        Result<Mesh_buffers> r;
        r.status =
            Status::error(Status_code::invalid_mesh,
                          at(line) + "face index " +
                              std::string(tok[i].substr(0, tok[i].find('/'))) +
                              " is out of range (OBJ indices start at 1)",
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
  } else if (k == "t") {
    Result<Mesh_buffers> r;
    if (!read_tag(tok, line, tags, r)) return r;
  } else if (!is_ignored_obj_statement(k)) {
    return parse_failure(line, "unknown OBJ statement " + quoted(k));
  }
  return {};
}

/// A failure of a statement that runs from line `first` to line `last`
/// (continued with backslashes): "line 7 (continued to line 9): ..." where
/// the message said "line 7: ...". The status keeps line 7, where the
/// statement starts.
Result<Mesh_buffers> continued_failure(Result<Mesh_buffers>&& r, int first,
                                       int last) {
  const std::string prefix = at(first);
  if (last > first && r.status.message.rfind(prefix, 0) == 0) {
    r.status.message = "line " + std::to_string(first) +
                       " (continued to line " + std::to_string(last) +
                       "): " + r.status.message.substr(prefix.size());
  }
  return std::move(r);
}

Result<Mesh_buffers> read_obj(std::string_view text,
                              std::vector<std::uint32_t>* corner_halfedges,
                              const Read_options& options, bool fast) {
  Line_reader in(text);
  in.read_continuations();
  std::vector<std::string_view> tok;
  int line = 0;
  Mesh_buffers mesh;
  std::vector<int> face_lines;
  Tag_list tags;
  while (fast_obj_run(in, fast, mesh, face_lines, line) ==
         Run_stop::slow_line) {
    in.take_line(tok);
    // A line of a lone backslash continued into blanks holds no statement.
    if (tok.empty()) continue;
    Result<Mesh_buffers> r =
        read_obj_statement(tok, line, mesh, face_lines, tags);
    if (!r.ok()) {
      return continued_failure(std::move(r), line, line + in.continued_lines());
    }
  }
  return finish(std::move(mesh), face_lines, 1, corner_halfedges,
                std::move(tags), options);
}

// ---------------------------------------------------------------- writing

using detail::Chunk_writer;
using detail::write_g17;
using detail::write_uint;

/// A sharpness as its shortest "%.Ng" that reads back as the same float,
/// preferring a form without an exponent ("10", not "1e+01"); 9 significant
/// digits always do. snprintf, not std::to_chars (em++ 3.1.6's libc++ has no
/// floating-point one); tags are few.
std::string float_text(float x) {
  char buf[32];
  std::string with_exponent;
  for (int precision = 1; precision <= 9; ++precision) {
    const int n = std::snprintf(buf, sizeof buf, "%.*g", precision,
                                static_cast<double>(x));
    double back = 0;
    fast_float::from_chars(buf, buf + n, back);
    if (static_cast<float>(back) != x) continue;
    if (std::memchr(buf, 'e', static_cast<std::size_t>(n)) == nullptr)
      return std::string(buf, static_cast<std::size_t>(n));
    if (with_exponent.empty())
      with_exponent.assign(buf, static_cast<std::size_t>(n));
  }
  if (!with_exponent.empty()) return with_exponent;
  std::snprintf(buf, sizeof buf, "%.9g", static_cast<double>(x));
  return buf;
}

/// The tags as OpenSubdiv's tag lines, after the faces: in OBJ as they are,
/// in OFF as comments ("# t ..."), which SubdivLab reads back and other
/// readers skip. One crease edge or corner per line (each with its own
/// sharpness), holes 16 to a line. Notes are not written.
void write_tags(const Mesh_tags& tags, bool off, Chunk_writer& out) {
  const char* const start = off ? "# t " : "t ";
  std::string line;
  for (std::size_t i = 0; i < tags.crease_sharpness.size(); ++i) {
    line = start;
    line += "crease 2/1/0 " + std::to_string(tags.crease_edges[2 * i]) + " " +
            std::to_string(tags.crease_edges[2 * i + 1]) + " " +
            float_text(tags.crease_sharpness[i]) + "\n";
    out.put(line);
  }
  for (std::size_t i = 0; i < tags.corner_sharpness.size(); ++i) {
    line = start;
    line += "corner 1/1/0 " + std::to_string(tags.corner_vertices[i]) + " " +
            float_text(tags.corner_sharpness[i]) + "\n";
    out.put(line);
  }
  constexpr std::size_t holes_per_line = 16;
  for (std::size_t i = 0; i < tags.holes.size(); i += holes_per_line) {
    const std::size_t n = std::min(holes_per_line, tags.holes.size() - i);
    line = start;
    line += "hole " + std::to_string(n) + "/0/0";
    for (std::size_t j = i; j < i + n; ++j)
      line += " " + std::to_string(tags.holes[j]);
    out.put(line + "\n");
  }
  if (tags.boundary_given ||
      tags.boundary != Boundary_interpolation::edge_only) {
    const char* value =
        tags.boundary == Boundary_interpolation::none              ? "0"
        : tags.boundary == Boundary_interpolation::edge_and_corner ? "1"
                                                                   : "2";
    out.put(std::string(start) + "interpolateboundary 1/0/0 " + value + "\n");
  }
  if (tags.crease_method_given ||
      tags.crease_method != Crease_method::uniform) {
    out.put(
        std::string(start) + "creasemethod 0/0/1 " +
        (tags.crease_method == Crease_method::chaikin ? "chaikin" : "normal") +
        "\n");
  }
}

/// Upper-case name of a format, for messages ("OFF").
std::string format_label(Mesh_format format) {
  std::string name = format_name(format);
  for (char& c : name) c = static_cast<char>(c - 'a' + 'A');
  return name;
}

/// A parse error that quotes a line of a file that is no text of `format`
/// (a binary file, or a file of another format named with this one's
/// extension) says what the file looks like instead of quoting its bytes
/// as a bad header or number: "This looks like a binary STL file, not OFF
/// text: ..." Errors of the format's own data (a binary PLY's byte
/// offsets, line 0; its header's lines) and files of the format keep their
/// message.
Result<Mesh_buffers> name_misread_file(Result<Mesh_buffers>&& r,
                                       std::string_view text,
                                       Mesh_format format) {
  if (r.status.code != Status_code::parse_error || r.status.line == 0)
    return std::move(r);
  const std::string asked = format_label(format);
  const Result<Mesh_format> seen = detect_format(text);
  std::string what;
  if (seen.ok() && seen.value != format) {
    const bool binary_stl =
        seen.value == Mesh_format::stl && detail::is_binary_stl(text);
    const std::string other = format_label(seen.value);
    // "an OFF", "an OBJ", "an STL" (said letter by letter), "a PLY".
    const std::string article = seen.value == Mesh_format::ply ? "a " : "an ";
    what = "This looks like " +
           (binary_stl ? "a binary STL" : article + other) + " file, not " +
           asked + (binary_stl ? " text" : "") + ": give it the ." +
           format_name(seen.value) + " extension to read it as " + other + ".";
  } else {
    // A PLY's header is text before data that may be binary: its messages
    // quote the header.
    if (format == Mesh_format::ply && text.substr(0, 3) == "ply")
      return std::move(r);
    // PLY may be binary after its header: "not a PLY file".
    const std::string not_what =
        format == Mesh_format::ply ? "a PLY file" : asked + " text";
    if (detail::looks_utf16(text)) {
      what =
          "This looks like UTF-16 text (what Windows Notepad saves as "
          "\"Unicode\"), not " +
          not_what +
          " in UTF-8 or ASCII: save it again as UTF-8 and open that.";
      Result<Mesh_buffers> named;
      named.status = Status::error(Status_code::parse_error, what);
      return named;
    }
    const detail::Text_share share = detail::text_share(text);
    if (!detail::looks_binary(share)) return std::move(r);
    what = "This looks like a binary file, not " + not_what + ": " +
           std::to_string(share.non_text) + " of its first " +
           std::to_string(share.sample) +
           " bytes are control bytes or no UTF-8 text. " + detail::formats_read;
  }
  Result<Mesh_buffers> named;
  named.status = Status::error(Status_code::parse_error, what);
  return named;
}

/// read_mesh, with or without the fast path (OFF and OBJ).
Result<Mesh_buffers> read_text(std::string_view text, Mesh_format format,
                               std::vector<std::uint32_t>* corner_halfedges,
                               const Read_options& options, bool fast) {
  try {
    // A binary STL's 80-byte header is free text: its size, not its first
    // bytes, says what it is.
    if (format != Mesh_format::stl || !detail::is_binary_stl(text)) {
      Result<Mesh_buffers> r;
      r.status = detail::check_not_other_file(text);
      if (!r.ok()) return r;
    }
    Result<Mesh_buffers> r;
    switch (format) {
      case Mesh_format::off:
        r = read_off(text, corner_halfedges, options, fast);
        break;
      case Mesh_format::obj:
        r = read_obj(text, corner_halfedges, options, fast);
        break;
      case Mesh_format::ply:
        r = detail::read_ply(text, corner_halfedges, options);
        break;
      case Mesh_format::stl:
        r = detail::read_stl(text, corner_halfedges, options);
        break;
      default:
        return parse_failure(0, "unknown mesh format");
    }
    return name_misread_file(std::move(r), text, format);
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

}  // namespace

Result<Mesh_buffers> read_mesh(std::string_view text, Mesh_format format,
                               std::vector<std::uint32_t>* corner_halfedges,
                               const Read_options& options) {
  return read_text(text, format, corner_halfedges, options, true);
}

const char* format_name(Mesh_format format) {
  switch (format) {
    case Mesh_format::off:
      return "off";
    case Mesh_format::obj:
      return "obj";
    case Mesh_format::ply:
      return "ply";
    case Mesh_format::stl:
      return "stl";
  }
  return "off";
}

Result<Mesh_format> detect_format(std::string_view bytes) {
  Result<Mesh_format> r;
  if (detail::is_binary_stl(bytes)) {
    r.value = Mesh_format::stl;
    return r;
  }
  r.status = detail::check_not_other_file(bytes);
  if (!r.ok()) return r;
  // The first line that holds anything but blanks and comments.
  std::string_view rest = bytes.substr(0, 1 << 16);
  if (rest.substr(0, 3) == "\xEF\xBB\xBF") rest.remove_prefix(3);
  if (rest.substr(0, 3) == "ply" &&
      (rest.size() == 3 || rest[3] == '\n' || rest[3] == '\r')) {
    r.value = Mesh_format::ply;
    return r;
  }
  while (!rest.empty()) {
    std::size_t eol = rest.find_first_of("\r\n");
    if (eol == std::string_view::npos) eol = rest.size();
    std::string_view line = rest.substr(0, eol);
    rest.remove_prefix(std::min(eol + 1, rest.size()));
    const std::size_t b = line.find_first_not_of(" \t");
    if (b == std::string_view::npos || line[b] == '#') continue;
    line.remove_prefix(b);
    const std::string_view word = line.substr(0, line.find_first_of(" \t"));
    if (word == "solid") {
      r.value = Mesh_format::stl;
      return r;
    }
    const std::size_t off = word.find("OFF");
    if (off != std::string_view::npos && off + 3 == word.size() &&
        word.find_first_not_of("STCN4n") == off) {
      r.value = Mesh_format::off;
      return r;
    }
    for (const char* k :
         {"v", "vn", "vt", "f", "o", "g", "s", "mtllib", "usemtl"}) {
      if (word == k && word.size() < line.size()) {
        r.value = Mesh_format::obj;
        return r;
      }
    }
    break;
  }
  r.status = Status::error(
      Status_code::parse_error,
      std::string("This is not a mesh file: no OFF, OBJ, PLY or STL header "
                  "or statement at its start. ") +
          detail::formats_read);
  return r;
}

namespace detail {
Result<Mesh_buffers> read_mesh_general(
    std::string_view text, Mesh_format format,
    std::vector<std::uint32_t>* corner_halfedges) {
  return read_text(text, format, corner_halfedges, {}, false);
}
}  // namespace detail

namespace {

/// check_writable's part for the tags: what read_mesh would refuse when
/// reading them back (sizes that do not match, indices out of range, a
/// sharpness that is negative or not finite, a crease that is not an edge).
Status check_writable_tags(const Mesh_buffers& mesh) {
  const Mesh_tags& t = mesh.tags;
  const auto bad = [](const std::string& what) {
    return Status::error(Status_code::invalid_mesh, "tags: " + what);
  };
  if (t.crease_edges.size() != 2 * t.crease_sharpness.size()) {
    return bad(std::to_string(t.crease_edges.size()) + " crease vertices for " +
               std::to_string(t.crease_sharpness.size()) +
               " sharpness values (two vertices per sharpness)");
  }
  if (t.corner_vertices.size() != t.corner_sharpness.size()) {
    return bad(std::to_string(t.corner_vertices.size()) +
               " corner vertices for " +
               std::to_string(t.corner_sharpness.size()) +
               " sharpness values (one vertex per sharpness)");
  }
  const std::size_t nv = mesh.vertex_count(), nf = mesh.face_count();
  for (const std::uint32_t v : t.crease_edges) {
    if (v >= nv) {
      return bad("crease vertex " + std::to_string(v) + " is out of range (" +
                 std::to_string(nv) + " vertices)");
    }
  }
  for (const std::uint32_t v : t.corner_vertices) {
    if (v >= nv) {
      return bad("corner vertex " + std::to_string(v) + " is out of range (" +
                 std::to_string(nv) + " vertices)");
    }
  }
  for (const std::uint32_t f : t.holes) {
    if (f >= nf) {
      return bad("hole face " + std::to_string(f) + " is out of range (" +
                 std::to_string(nf) + " faces)");
    }
  }
  for (const std::vector<float>* values :
       {&t.crease_sharpness, &t.corner_sharpness}) {
    for (const float s : *values) {
      if (!(s >= 0) || !std::isfinite(s)) {
        return bad(
            std::string(values == &t.crease_sharpness ? "crease" : "corner") +
            " sharpness " + std::to_string(s) +
            " is not a finite number 0 or more");
      }
    }
  }
  if (t.crease_edges.empty()) return Status::success();
  std::vector<std::uint64_t> edges;
  edges.reserve(mesh.face_indices.size());
  std::size_t o = 0;
  for (const std::uint32_t k : mesh.face_sizes) {
    for (std::uint32_t c = 0; c < k; ++c) {
      const std::uint64_t a = mesh.face_indices[o + c],
                          b = mesh.face_indices[o + (c + 1) % k];
      edges.push_back(a < b ? a << 32 | b : b << 32 | a);
    }
    o += k;
  }
  std::sort(edges.begin(), edges.end());
  for (std::size_t i = 0; i < t.crease_edges.size(); i += 2) {
    const std::uint64_t a = t.crease_edges[i], b = t.crease_edges[i + 1];
    if (!std::binary_search(edges.begin(), edges.end(),
                            a < b ? a << 32 | b : b << 32 | a)) {
      return bad("crease " + std::to_string(a) + " " + std::to_string(b) +
                 " is not an edge of the mesh");
    }
  }
  return Status::success();
}

}  // namespace

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
  return check_writable_tags(mesh);
}

bool write_mesh_chunks(const Mesh_buffers& mesh, Mesh_format format,
                       std::size_t max_chunk_bytes, const Chunk_sink& sink,
                       std::string_view comment) {
  if (format == Mesh_format::ply)
    return detail::write_ply_chunks(mesh, max_chunk_bytes, sink, comment);
  if (format == Mesh_format::stl)
    return detail::write_stl_chunks(mesh, max_chunk_bytes, sink, comment);
  Chunk_writer out(std::max(max_chunk_bytes, min_chunk_bytes), sink);
  std::string comment_line;
  if (!comment.empty()) {
    comment_line = "# " + std::string(comment) + "\n";
    for (std::size_t i = 0; i + 1 < comment_line.size(); ++i)
      if (comment_line[i] == '\n' || comment_line[i] == '\r')
        comment_line[i] = ' ';
  }
  const std::size_t nv = mesh.vertex_count(), nf = mesh.face_count();
  const bool off = format == Mesh_format::off;
  if (off) {
    char* p = out.reserve();
    std::memcpy(p, "OFF\n", 4);
    out.commit(p + 4);
    out.put(comment_line);
    p = write_uint(nv, out.reserve());
    *p++ = ' ';
    out.commit(p);
    p = write_uint(nf, out.reserve());
    std::memcpy(p, " 0\n", 3);
    out.commit(p + 3);
  }
  if (!off) out.put(comment_line);
  const double* xyz = mesh.positions.data();
  for (std::size_t v = 0; v < nv && out.ok(); ++v, xyz += 3) {
    char* p = out.reserve();
    if (!off) *p++ = 'v', *p++ = ' ';
    p = write_g17(xyz[0], p);
    *p++ = ' ';
    out.commit(p);
    p = write_g17(xyz[1], out.reserve());
    *p++ = ' ';
    out.commit(p);
    p = write_g17(xyz[2], out.reserve());
    *p++ = '\n';
    out.commit(p);
  }
  const std::uint32_t* index = mesh.face_indices.data();
  const std::uint64_t base = off ? 0 : 1;
  for (std::size_t f = 0; f < nf && out.ok(); ++f) {
    const std::uint32_t k = mesh.face_sizes[f];
    char* p = out.reserve();
    if (off) {
      p = write_uint(k, p);
    } else {
      *p++ = 'f';
    }
    for (std::uint32_t i = 0; i < k; ++i) {
      *p++ = ' ';
      p = write_uint(base + index[i], p);
      out.commit(p);
      p = out.reserve();
    }
    *p++ = '\n';
    out.commit(p);
    index += k;
  }
  if (out.ok()) write_tags(mesh.tags, off, out);
  return out.finish();
}

std::string write_mesh(const Mesh_buffers& mesh, Mesh_format format,
                       std::string_view comment) {
  std::string text;
  text.reserve(mesh.vertex_count() * 60 + mesh.face_indices.size() * 8 +
               mesh.face_count() * 4 + 32);
  write_mesh_chunks(
      mesh, format, std::size_t{1} << 16,
      [&text](std::string_view chunk) {
        text.append(chunk);
        return true;
      },
      comment);
  return text;
}

}  // namespace subdivlab
