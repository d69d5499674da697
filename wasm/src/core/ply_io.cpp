// PLY in and out. Owner of ply_io.h.
//
// Written by hand rather than with CGAL's PLY reader (CGAL/IO/PLY.h): that
// one reports failure as a bare false (no line, no byte offset), trusts the
// header's counts when it allocates, and reads through std::istream; this
// one keeps read_mesh's promises (a message naming the line or byte, never
// more memory than the data backs, never a throw).

#include "ply_io.h"

#include <algorithm>
#include <cctype>
#include <charconv>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>
#include <string>
#include <string_view>
#include <vector>

// Correctly rounded decimal -> double, as mesh_io.cpp reads OFF and OBJ.
#include <fast_float/fast_float.h>

#include "file_kind.h"
#include "mesh_check.h"
#include "orientation_repair.h"
#include "parse_failure.h"
#include "text_writer.h"

namespace subdivlab::detail {
namespace {

enum class Ply_type : std::uint8_t {
  int8,
  uint8,
  int16,
  uint16,
  int32,
  uint32,
  float32,
  float64
};

struct Type_name {
  std::string_view name;
  Ply_type type;
};

// The PLY 1.0 names and their sized aliases.
constexpr Type_name type_names[] = {
    {"char", Ply_type::int8},      {"int8", Ply_type::int8},
    {"uchar", Ply_type::uint8},    {"uint8", Ply_type::uint8},
    {"short", Ply_type::int16},    {"int16", Ply_type::int16},
    {"ushort", Ply_type::uint16},  {"uint16", Ply_type::uint16},
    {"int", Ply_type::int32},      {"int32", Ply_type::int32},
    {"uint", Ply_type::uint32},    {"uint32", Ply_type::uint32},
    {"float", Ply_type::float32},  {"float32", Ply_type::float32},
    {"double", Ply_type::float64}, {"float64", Ply_type::float64}};

std::size_t type_size(Ply_type t) {
  switch (t) {
    case Ply_type::int8:
    case Ply_type::uint8:
      return 1;
    case Ply_type::int16:
    case Ply_type::uint16:
      return 2;
    case Ply_type::float64:
      return 8;
    default:
      return 4;
  }
}

bool is_integer(Ply_type t) { return t < Ply_type::float32; }

/// The PLY name of a type ("uchar", "float" ...).
std::string_view type_name(Ply_type t) {
  for (const Type_name& n : type_names)
    if (n.type == t) return n.name;
  return "?";
}

struct Ply_property {
  std::string_view name;
  bool list = false;
  Ply_type count_type = Ply_type::uint8;
  Ply_type type = Ply_type::float32;
};

struct Ply_element {
  std::string_view name;
  std::uint64_t count = 0;
  std::vector<Ply_property> properties;
  int line = 0;
};

enum class Encoding { ascii, little, big };

std::vector<std::string_view> split(std::string_view line) {
  std::vector<std::string_view> out;
  std::size_t i = 0;
  while (i < line.size()) {
    while (i < line.size() && (line[i] == ' ' || line[i] == '\t')) ++i;
    const std::size_t b = i;
    while (i < line.size() && line[i] != ' ' && line[i] != '\t') ++i;
    if (i > b) out.push_back(line.substr(b, i - b));
  }
  return out;
}

bool find_type(std::string_view name, Ply_type& t) {
  for (const Type_name& n : type_names) {
    if (n.name == name) {
      t = n.type;
      return true;
    }
  }
  return false;
}

/// The header: format, elements, where the data starts.
struct Ply_header {
  Encoding encoding = Encoding::ascii;
  std::vector<Ply_element> elements;
  std::size_t data_begin = 0;
  int data_line = 0;  ///< line of the first data byte (ASCII)
};

Result<Mesh_buffers> read_header(std::string_view bytes, Ply_header& h) {
  std::size_t pos = 0;
  int line = 0;
  bool have_format = false;
  for (;;) {
    if (pos >= bytes.size())
      return parse_failure(line, "the header ends without an end_header line");
    std::size_t eol = bytes.find('\n', pos);
    if (eol == std::string_view::npos) eol = bytes.size();
    std::string_view text = bytes.substr(pos, eol - pos);
    if (!text.empty() && text.back() == '\r') text.remove_suffix(1);
    pos = eol + 1;
    ++line;
    if (line == 1) {
      if (text != "ply")
        return parse_failure(
            1, "a PLY file starts with the line 'ply', not " + quoted(text));
      continue;
    }
    const std::vector<std::string_view> tok = split(text);
    if (tok.empty() || tok[0] == "comment" || tok[0] == "obj_info") continue;
    if (tok[0] == "end_header") {
      if (tok.size() != 1)
        return parse_failure(line, "end_header takes nothing after it");
      break;
    }
    if (tok[0] == "format") {
      if (tok.size() != 3 || tok[2] != "1.0")
        return parse_failure(line,
                             "expected 'format <ascii | binary_little_endian | "
                             "binary_big_endian> 1.0', not " +
                                 quoted(text));
      if (tok[1] == "ascii") {
        h.encoding = Encoding::ascii;
      } else if (tok[1] == "binary_little_endian") {
        h.encoding = Encoding::little;
      } else if (tok[1] == "binary_big_endian") {
        h.encoding = Encoding::big;
      } else {
        return parse_failure(line, "unknown PLY format " + quoted(tok[1]) +
                                       " (ascii, binary_little_endian or "
                                       "binary_big_endian)");
      }
      have_format = true;
      continue;
    }
    if (!have_format)
      return parse_failure(
          line, "the 'format' line must come before " + quoted(tok[0]));
    if (tok[0] == "element") {
      if (tok.size() != 3)
        return parse_failure(
            line, "expected 'element <name> <count>', not " + quoted(text));
      Ply_element e;
      e.name = tok[1];
      e.line = line;
      const auto [end, ec] = std::from_chars(
          tok[2].data(), tok[2].data() + tok[2].size(), e.count);
      if (ec != std::errc() || end != tok[2].data() + tok[2].size())
        return parse_failure(line, "the count of element " + quoted(e.name) +
                                       " is " + quoted(tok[2]) +
                                       ", not a whole number 0 or more");
      h.elements.push_back(e);
      continue;
    }
    if (tok[0] == "property") {
      if (h.elements.empty())
        return parse_failure(line, "'property' before any 'element'");
      Ply_property p;
      std::size_t t = 1;
      if (tok.size() > 1 && tok[1] == "list") {
        p.list = true;
        if (tok.size() != 5)
          return parse_failure(line,
                               "expected 'property list <count type> <index "
                               "type> <name>', not " +
                                   quoted(text));
        if (!find_type(tok[2], p.count_type))
          return parse_failure(line, "unknown PLY type " + quoted(tok[2]));
        if (!is_integer(p.count_type))
          return parse_failure(line,
                               "the list " + quoted(tok[4]) +
                                   " has a count of "
                                   "type " +
                                   quoted(tok[2]) +
                                   "; a list count must be an integer type");
        t = 3;
      } else if (tok.size() != 3) {
        return parse_failure(
            line, "expected 'property <type> <name>', not " + quoted(text));
      }
      if (!find_type(tok[t], p.type))
        return parse_failure(line, "unknown PLY type " + quoted(tok[t]));
      p.name = tok[t + 1];
      h.elements.back().properties.push_back(p);
      continue;
    }
    return parse_failure(line, "unknown header line " + quoted(text));
  }
  h.data_begin = std::min(pos, bytes.size());
  h.data_line = line + 1;
  return {};
}

/// Where the vertex and face data are, after checking the header has them.
struct Ply_layout {
  std::size_t vertex_element = 0, face_element = 0;
  std::size_t xyz[3] = {0, 0, 0};
  std::size_t indices = 0;
};

Result<Mesh_buffers> find_layout(const Ply_header& h, Ply_layout& l) {
  const std::size_t none = static_cast<std::size_t>(-1);
  l.vertex_element = l.face_element = none;
  for (std::size_t e = 0; e < h.elements.size(); ++e) {
    if (h.elements[e].name == "vertex" && l.vertex_element == none)
      l.vertex_element = e;
    if (h.elements[e].name == "face" && l.face_element == none)
      l.face_element = e;
  }
  if (l.vertex_element == none)
    return parse_failure(0, "the header declares no 'vertex' element");
  if (l.face_element == none)
    return parse_failure(0,
                         "the header declares no 'face' element: a point cloud "
                         "is not a polygon mesh");
  const Ply_element& v = h.elements[l.vertex_element];
  const char* axes[3] = {"x", "y", "z"};
  for (int a = 0; a < 3; ++a) {
    l.xyz[a] = none;
    for (std::size_t p = 0; p < v.properties.size(); ++p) {
      if (v.properties[p].name != axes[a]) continue;
      if (v.properties[p].list)
        return parse_failure(v.line, std::string("the vertex property '") +
                                         axes[a] + "' is a list, not a number");
      l.xyz[a] = p;
      break;
    }
    if (l.xyz[a] == none)
      return parse_failure(v.line, std::string("the vertex element has no '") +
                                       axes[a] + "' property");
  }
  const Ply_element& f = h.elements[l.face_element];
  l.indices = none;
  for (std::size_t p = 0; p < f.properties.size(); ++p) {
    if (f.properties[p].name != "vertex_indices" &&
        f.properties[p].name != "vertex_index")
      continue;
    if (!f.properties[p].list)
      return parse_failure(f.line,
                           "the face property " + quoted(f.properties[p].name) +
                               " is a single number, not a list of vertices");
    if (!is_integer(f.properties[p].type))
      return parse_failure(f.line, "the face list " +
                                       quoted(f.properties[p].name) +
                                       " holds floating-point numbers; vertex "
                                       "indices must be of an integer type");
    l.indices = p;
    break;
  }
  if (l.indices == none)
    return parse_failure(f.line,
                         "the face element has no 'vertex_indices' list");
  if (v.count > 0xFFFFFFFFull)
    return parse_failure(v.line, "more vertices than 32-bit indices can name");
  return {};
}

/// Reads the values of the data section, one at a time, as doubles (every
/// PLY type fits in one exactly).
class Value_source {
 public:
  Value_source(std::string_view bytes, const Ply_header& h)
      : data_(bytes.substr(h.data_begin)),
        begin_offset_(h.data_begin),
        encoding_(h.encoding),
        line_(h.data_line) {}

  /// Reads one value of type t; false at the end of the data or (ASCII) on
  /// a token that is not a number of that type (`bad` set).
  bool next(Ply_type t, double& out) {
    if (encoding_ != Encoding::ascii) return next_binary(t, out);
    if (!next_token()) return false;
    token_line_ = line_;
    const char* b = token_.data();
    const char* e = b + token_.size();
    if (is_integer(t)) {
      long long v = 0;
      if (b != e && *b == '+') ++b;
      const auto [end, ec] = std::from_chars(b, e, v);
      if (ec != std::errc() || end != e || !in_range(t, v)) {
        bad_ = true;
        return false;
      }
      out = static_cast<double>(v);
      return true;
    }
    if (b != e && *b == '+') ++b;
    const auto [end, ec] = fast_float::from_chars(b, e, out);
    if (ec != std::errc() || end != e) {
      bad_ = true;
      return false;
    }
    return true;
  }

  bool bad() const { return bad_; }
  std::string_view token() const { return token_; }
  /// Line of the last token read (ASCII).
  int line() const { return token_line_; }
  /// Line where the next token would be looked for (ASCII).
  int current_line() const { return line_; }
  /// Offset in the file of the next byte to read (binary).
  std::size_t offset() const { return begin_offset_ + pos_; }
  std::size_t remaining() const { return data_.size() - pos_; }
  bool ascii() const { return encoding_ == Encoding::ascii; }

  /// Whether anything but blanks is left.
  bool rest_is_blank() {
    if (!ascii()) {
      for (std::size_t i = pos_; i < data_.size(); ++i)
        if (!std::isspace(static_cast<unsigned char>(data_[i]))) return false;
      return true;
    }
    if (!next_token()) return true;
    token_line_ = line_;
    return false;
  }

 private:
  static bool in_range(Ply_type t, long long v) {
    switch (t) {
      case Ply_type::int8:
        return v >= -128 && v <= 127;
      case Ply_type::uint8:
        return v >= 0 && v <= 255;
      case Ply_type::int16:
        return v >= -32768 && v <= 32767;
      case Ply_type::uint16:
        return v >= 0 && v <= 65535;
      case Ply_type::int32:
        return v >= -2147483648LL && v <= 2147483647LL;
      default:
        return v >= 0 && v <= 4294967295LL;
    }
  }

  bool next_token() {
    while (pos_ < data_.size()) {
      const char c = data_[pos_];
      if (c == '\n') {
        ++line_;
      } else if (c == '\r') {
        if (pos_ + 1 >= data_.size() || data_[pos_ + 1] != '\n') ++line_;
      } else if (c != ' ' && c != '\t' && c != '\f' && c != '\v') {
        break;
      }
      ++pos_;
    }
    if (pos_ >= data_.size()) return false;
    const std::size_t b = pos_;
    while (pos_ < data_.size() &&
           !std::isspace(static_cast<unsigned char>(data_[pos_])))
      ++pos_;
    token_ = data_.substr(b, pos_ - b);
    return true;
  }

  bool next_binary(Ply_type t, double& out) {
    const std::size_t n = type_size(t);
    if (data_.size() - pos_ < n) return false;
    unsigned char b[8];
    std::memcpy(b, data_.data() + pos_, n);
    pos_ += n;
    // Assemble the value from its bytes in the file's order: independent of
    // the machine's (WebAssembly is little-endian, some hosts are not).
    std::uint64_t u = 0;
    for (std::size_t i = 0; i < n; ++i) {
      const std::size_t k = encoding_ == Encoding::little ? n - 1 - i : i;
      u = u << 8 | b[k];
    }
    switch (t) {
      case Ply_type::int8:
        out = static_cast<std::int8_t>(u);
        break;
      case Ply_type::uint8:
      case Ply_type::uint16:
      case Ply_type::uint32:
        out = static_cast<double>(u);
        break;
      case Ply_type::int16:
        out = static_cast<std::int16_t>(u);
        break;
      case Ply_type::int32:
        out = static_cast<std::int32_t>(u);
        break;
      case Ply_type::float32: {
        const auto bits = static_cast<std::uint32_t>(u);
        float f;
        std::memcpy(&f, &bits, 4);
        out = f;
        break;
      }
      case Ply_type::float64:
        std::memcpy(&out, &u, 8);
        break;
    }
    return true;
  }

  std::string_view data_;
  std::size_t begin_offset_;
  Encoding encoding_;
  std::size_t pos_ = 0;
  int line_;
  int token_line_ = 0;
  std::string_view token_;
  bool bad_ = false;
};

/// The least number of bytes one element takes: a binary value's size, or
/// in ASCII a digit and a separator per value (lists: their count).
std::size_t min_element_bytes(const Ply_element& e, bool ascii) {
  std::size_t n = 0;
  for (const Ply_property& p : e.properties)
    n += ascii ? 2 : type_size(p.list ? p.count_type : p.type);
  return n;
}

std::string element_name(const Ply_element& e, std::uint64_t i) {
  // The name as the header gave it, control bytes escaped (the one-line
  // message a CLI prints).
  return printable(e.name) + " " + std::to_string(i) + " (of " +
         std::to_string(e.count) + ")";
}

/// What the value read for `part` of `p` should have been ("uchar value").
std::string type_label(const Ply_property& p, const char* part) {
  const Ply_type t = p.list && std::string_view(part).rfind("the count", 0) == 0
                         ? p.count_type
                         : p.type;
  return std::string(type_name(t)) + " value";
}

/// The message for a value that could not be read.
Result<Mesh_buffers> value_fail(const Value_source& in, const Ply_element& e,
                                std::uint64_t i, const Ply_property& p,
                                const char* part) {
  const std::string what =
      std::string(part) + quoted(p.name) + " of " + element_name(e, i);
  if (in.ascii()) {
    if (in.bad())
      return parse_failure(in.line(), quoted(in.token()) + " is not a " +
                                          std::string(type_label(p, part)) +
                                          " for " + what);
    return parse_failure(in.current_line(), "the data ends before " + what +
                                                " (the header declares " +
                                                std::to_string(e.count) + ")");
  }
  return parse_failure(0, "byte " + std::to_string(in.offset()) +
                              ": the data ends before " + what +
                              " (the header "
                              "declares " +
                              std::to_string(e.count) + ")");
}

}  // namespace

Result<Mesh_buffers> read_ply(std::string_view bytes,
                              std::vector<std::uint32_t>* corner_halfedges,
                              const Read_options& options) {
  Ply_header h;
  Result<Mesh_buffers> r = read_header(bytes, h);
  if (!r.ok()) return r;
  Ply_layout l;
  r = find_layout(h, l);
  if (!r.ok()) return r;
  const bool ascii = h.encoding == Encoding::ascii;
  // Counts the data cannot back are refused before anything is reserved.
  std::size_t left = bytes.size() - h.data_begin;
  for (const Ply_element& e : h.elements) {
    const std::size_t min = min_element_bytes(e, ascii);
    if (min == 0 || e.count == 0) continue;
    if (e.count > left / min) {
      return parse_failure(
          e.line, "the header declares " + std::to_string(e.count) + " " +
                      quoted(e.name) + " elements of at least " +
                      std::to_string(min) + " bytes each, but only " +
                      std::to_string(bytes.size() - h.data_begin) +
                      " bytes of data follow");
    }
    left -= static_cast<std::size_t>(e.count) * min;
  }
  Mesh_buffers mesh;
  std::vector<int> face_lines;
  const Ply_element& ve = h.elements[l.vertex_element];
  const Ply_element& fe = h.elements[l.face_element];
  mesh.positions.reserve(3 * static_cast<std::size_t>(ve.count));
  mesh.face_sizes.reserve(static_cast<std::size_t>(fe.count));
  if (ascii) face_lines.reserve(static_cast<std::size_t>(fe.count));
  Value_source in(bytes, h);
  for (std::size_t ei = 0; ei < h.elements.size(); ++ei) {
    const Ply_element& e = h.elements[ei];
    const bool is_vertex = ei == l.vertex_element;
    const bool is_face = ei == l.face_element;
    // An element without properties holds no data (nor is it the vertex or
    // face element, which need theirs): its count, up to 2^64 - 1, costs
    // nothing.
    if (e.properties.empty()) continue;
    for (std::uint64_t i = 0; i < e.count; ++i) {
      double xyz[3] = {0, 0, 0};
      for (std::size_t pi = 0; pi < e.properties.size(); ++pi) {
        const Ply_property& p = e.properties[pi];
        double v = 0;
        if (!p.list) {
          if (!in.next(p.type, v)) return value_fail(in, e, i, p, "");
          if (is_vertex) {
            for (int a = 0; a < 3; ++a) {
              if (l.xyz[a] != pi) continue;
              if (!std::isfinite(v))
                return parse_failure(
                    in.ascii() ? in.line() : 0,
                    (in.ascii()
                         ? ""
                         : "byte " +
                               std::to_string(in.offset() - type_size(p.type)) +
                               ": ") +
                        "coordinate " + quoted(p.name) + " of " +
                        element_name(e, i) + " is not a finite number");
              xyz[a] = v;
            }
          }
          continue;
        }
        if (!in.next(p.count_type, v))
          return value_fail(in, e, i, p, "the count of list ");
        if (v < 0)
          return parse_failure(
              in.ascii() ? in.line() : 0,
              (in.ascii() ? "" : "byte " + std::to_string(in.offset()) + ": ") +
                  "the list " + quoted(p.name) + " of " + element_name(e, i) +
                  " has a negative count");
        const auto count = static_cast<std::uint64_t>(v);
        const int first_line = in.ascii() ? in.line() : 0;
        if (!in.ascii() && count > in.remaining() / type_size(p.type))
          return parse_failure(0, "byte " + std::to_string(in.offset()) +
                                      ": the list " + quoted(p.name) + " of " +
                                      element_name(e, i) + " has " +
                                      std::to_string(count) +
                                      " entries, more than the data holds");
        const bool indices = is_face && pi == l.indices;
        for (std::uint64_t k = 0; k < count; ++k) {
          if (!in.next(p.type, v))
            return value_fail(in, e, i, p, "an entry of list ");
          if (!indices) continue;
          if (v < 0)
            return parse_failure(
                first_line,
                (in.ascii() ? ""
                            : "byte " + std::to_string(in.offset()) + ": ") +
                    element_name(e, i) +
                    " has the negative vertex "
                    "index " +
                    std::to_string(static_cast<long long>(v)));
          mesh.face_indices.push_back(static_cast<std::uint32_t>(v));
        }
        if (indices) {
          if (count > 0xFFFFFFFFull)
            return parse_failure(first_line,
                                 element_name(e, i) + " is too large");
          mesh.face_sizes.push_back(static_cast<std::uint32_t>(count));
          if (ascii) face_lines.push_back(first_line);
        }
      }
      if (is_vertex) mesh.positions.insert(mesh.positions.end(), xyz, xyz + 3);
    }
  }
  if (!in.rest_is_blank()) {
    return ascii ? parse_failure(in.line(),
                                 "data after the last element the header "
                                 "declares: " +
                                     quoted(in.token()))
                 : parse_failure(0,
                                 "byte " + std::to_string(in.offset()) + ": " +
                                     std::to_string(in.remaining()) +
                                     " bytes after the last element the header "
                                     "declares");
  }
  Check_naming naming;
  if (ascii) naming.face_lines = &face_lines;
  return finish_read(std::move(mesh), naming, corner_halfedges,
                     options.repair_orientation);
}

bool write_ply_chunks(const Mesh_buffers& mesh, std::size_t max_chunk_bytes,
                      const Chunk_sink& sink, std::string_view comment) {
  Chunk_writer out(std::max(max_chunk_bytes, min_chunk_bytes), sink);
  std::uint32_t largest = 0;
  for (const std::uint32_t k : mesh.face_sizes) largest = std::max(largest, k);
  std::string header = "ply\nformat ascii 1.0\n";
  if (!comment.empty()) {
    std::string line(comment);
    for (char& c : line)
      if (c == '\n' || c == '\r') c = ' ';
    header += "comment " + line + "\n";
  }
  header += "element vertex " + std::to_string(mesh.vertex_count()) +
            "\nproperty double x\nproperty double y\nproperty double z\n"
            "element face " +
            std::to_string(mesh.face_count()) + "\nproperty list " +
            (largest <= 255 ? "uchar" : "uint") +
            " uint vertex_indices\nend_header\n";
  out.put(header);
  const double* xyz = mesh.positions.data();
  for (std::size_t v = 0; v < mesh.vertex_count() && out.ok(); ++v, xyz += 3) {
    for (int a = 0; a < 3; ++a) {
      char* p = write_g17(xyz[a], out.reserve());
      *p++ = a < 2 ? ' ' : '\n';
      out.commit(p);
    }
  }
  const std::uint32_t* index = mesh.face_indices.data();
  for (std::size_t f = 0; f < mesh.face_count() && out.ok(); ++f) {
    const std::uint32_t k = mesh.face_sizes[f];
    char* p = write_uint(k, out.reserve());
    out.commit(p);
    for (std::uint32_t i = 0; i < k; ++i) {
      p = out.reserve();
      *p++ = ' ';
      out.commit(write_uint(index[i], p));
    }
    p = out.reserve();
    *p++ = '\n';
    out.commit(p);
    index += k;
  }
  return out.finish();
}

}  // namespace subdivlab::detail
