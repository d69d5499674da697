// The only file that knows Emscripten: converts between JS values and the
// core's types, and catches everything so that no C++ exception (CGAL
// precondition failures included) ever crosses into JS and kills the
// instance. Every export returns a plain object:
//   { ok: true, ... }  or  { ok: false, code, message, line }.
// Mesh arrays leave the heap as copies (memory growth detaches any view).
#include <CGAL/assertions.h>
#include <CGAL/assertions_behaviour.h>
#include <CGAL/exceptions.h>
#include <emscripten/bind.h>
#include <emscripten/heap.h>
#include <emscripten/val.h>
#include <malloc.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <exception>
#include <limits>
#include <memory>
#include <new>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

#include "core/compare.h"
#include "core/curvature.h"
#include "core/euler_ops.h"
#include "core/halfedges.h"
#include "core/hausdorff.h"
#include "core/inspect.h"
#include "core/level_view.h"
#include "core/mesh_facts.h"
#include "core/mesh_io.h"
#include "core/mesh_types.h"
#include "core/render_buffers.h"
#include "core/stencils.h"
#include "core/subdivide.h"

using emscripten::val;

namespace subdivlab {
namespace {

/// Heap kept free beyond a step's predicted peak: the JS copies of the
/// result are made while the result is still in the heap, and dlmalloc's
/// free space is fragmented.
constexpr std::size_t heap_safety_margin = std::size_t{256} << 20;

val to_js_status(const Status& status) {
  val out = val::object();
  out.set("ok", false);
  out.set("code", std::string(status_code_name(status.code)));
  out.set("message", status.message);
  out.set("line", status.line);
  return out;
}

val ok_object() {
  val out = val::object();
  out.set("ok", true);
  return out;
}

template <class T>
val to_js_array(const char* type, const std::vector<T>& values) {
  // `new T(view)` copies: the JS array owns its bytes.
  return val::global(type).new_(
      emscripten::typed_memory_view(values.size(), values.data()));
}

/// A JS value that cannot be converted (an unknown option or tag name):
/// guarded() reports it as invalid_argument with its message.
struct Bad_argument : std::runtime_error {
  using std::runtime_error::runtime_error;
};

/// How a value that is not one of the names is quoted in a message.
std::string given_value(const val& v) {
  if (v.isString()) return "\"" + v.as<std::string>() + "\"";
  return "a " + v.typeOf().as<std::string>();
}

// The names of the tag enums in JS (web/core/mesh.ts).
const char* boundary_name(Boundary_interpolation b) {
  switch (b) {
    case Boundary_interpolation::edge_only:
      return "edge";
    case Boundary_interpolation::edge_and_corner:
      return "edge-and-corner";
    case Boundary_interpolation::none:
      return "none";
  }
  return "edge";
}

/// `what` names the value in the message ("Option boundary").
Boundary_interpolation boundary_from_js(const val& v, const char* what) {
  const std::string name = v.isString() ? v.as<std::string>() : "";
  for (const auto b :
       {Boundary_interpolation::edge_only,
        Boundary_interpolation::edge_and_corner, Boundary_interpolation::none})
    if (name == boundary_name(b)) return b;
  throw Bad_argument(
      std::string(what) +
      " must be \"edge\", \"edge-and-corner\" or \"none\", not " +
      given_value(v) + ".");
}

const char* crease_method_name(Crease_method m) {
  return m == Crease_method::chaikin ? "chaikin" : "uniform";
}

Crease_method crease_method_from_js(const val& v, const char* what) {
  const std::string name = v.isString() ? v.as<std::string>() : "";
  if (name == "uniform") return Crease_method::uniform;
  if (name == "chaikin") return Crease_method::chaikin;
  throw Bad_argument(std::string(what) +
                     " must be \"uniform\" or \"chaikin\", not " +
                     given_value(v) + ".");
}

val to_js_tags(const Mesh_tags& tags) {
  val out = val::object();
  out.set("creaseEdges", to_js_array("Uint32Array", tags.crease_edges));
  out.set("creaseSharpness",
          to_js_array("Float32Array", tags.crease_sharpness));
  out.set("cornerVertices", to_js_array("Uint32Array", tags.corner_vertices));
  out.set("cornerSharpness",
          to_js_array("Float32Array", tags.corner_sharpness));
  out.set("holes", to_js_array("Uint32Array", tags.holes));
  out.set("boundary", std::string(boundary_name(tags.boundary)));
  out.set("boundaryGiven", tags.boundary_given);
  out.set("creaseMethod", std::string(crease_method_name(tags.crease_method)));
  out.set("creaseMethodGiven", tags.crease_method_given);
  val notes = val::array();
  for (const std::string& note : tags.notes) notes.call<void>("push", note);
  out.set("notes", notes);
  return out;
}

val to_js_mesh(const Mesh_buffers& mesh) {
  val out = val::object();
  out.set("positions", to_js_array("Float64Array", mesh.positions));
  out.set("faceSizes", to_js_array("Uint32Array", mesh.face_sizes));
  out.set("faceIndices", to_js_array("Uint32Array", mesh.face_indices));
  out.set("controlEdges", to_js_array("Uint32Array", mesh.control_edges));
  if (mesh.tags.present()) out.set("tags", to_js_tags(mesh.tags));
  return out;
}

template <class T>
std::vector<T> from_js_array(const val& mesh, const char* key) {
  const val array = mesh[key];
  if (array.isUndefined() || array.isNull()) return {};
  return emscripten::convertJSArrayToNumberVector<T>(array);
}

Mesh_tags from_js_tags(const val& js) {
  Mesh_tags tags;
  tags.crease_edges = from_js_array<std::uint32_t>(js, "creaseEdges");
  tags.crease_sharpness = from_js_array<float>(js, "creaseSharpness");
  tags.corner_vertices = from_js_array<std::uint32_t>(js, "cornerVertices");
  tags.corner_sharpness = from_js_array<float>(js, "cornerSharpness");
  tags.holes = from_js_array<std::uint32_t>(js, "holes");
  const val boundary = js["boundary"];
  if (!boundary.isUndefined())
    tags.boundary = boundary_from_js(boundary, "Mesh tags' boundary");
  tags.boundary_given = js["boundaryGiven"].isTrue();
  const val method = js["creaseMethod"];
  if (!method.isUndefined())
    tags.crease_method =
        crease_method_from_js(method, "Mesh tags' creaseMethod");
  tags.crease_method_given = js["creaseMethodGiven"].isTrue();
  // Notes are the reader's words to the user; they do not go back in.
  return tags;
}

Mesh_buffers from_js_mesh(const val& mesh) {
  Mesh_buffers out;
  out.positions = from_js_array<double>(mesh, "positions");
  out.face_sizes = from_js_array<std::uint32_t>(mesh, "faceSizes");
  out.face_indices = from_js_array<std::uint32_t>(mesh, "faceIndices");
  out.control_edges = from_js_array<std::uint32_t>(mesh, "controlEdges");
  const val tags = mesh["tags"];
  if (!tags.isUndefined() && !tags.isNull()) out.tags = from_js_tags(tags);
  return out;
}

/// The UTF-8 bytes of a JS string or byte array, in the heap. The engine
/// writes them there itself (TextEncoder.encodeInto, TypedArray.set): a JS
/// string or Uint8Array given as std::string would cross in embind's loop,
/// one byte per iteration, and be copied again into the string.
struct Js_text {
  std::unique_ptr<char[]> bytes;  // not zeroed: every byte is written
  std::size_t size = 0;
  std::string_view view() const { return {bytes.get(), size}; }
};

/// `written` bytes of `text` from its UTF-16 unit `from` on, encoded at
/// `out` (room for `room` bytes); returns the units read.
std::size_t encode_into(const val& text, std::size_t from, char* out,
                        std::size_t room, std::size_t& written) {
  static const val encoder = val::global("TextEncoder").new_();
  const val rest = from == 0 ? text : text.call<val>("substring", from);
  const val done =
      encoder.call<val>("encodeInto", rest,
                        val(emscripten::typed_memory_view(
                            room, reinterpret_cast<unsigned char*>(out))));
  written = done["written"].as<std::size_t>();
  return done["read"].as<std::size_t>();
}

/// Reads a string (as UTF-8), a Uint8Array or another byte view, or an
/// ArrayBuffer; false for anything else.
bool from_js_text(const val& text, Js_text& out) {
  if (text.isString()) {
    // One byte per UTF-16 unit holds ASCII; anything else is re-encoded
    // from where it stopped, with the 3 bytes a unit may take.
    const std::size_t units = text["length"].as<std::size_t>();
    out.bytes.reset(new char[units + 1]);
    std::size_t written = 0;
    const std::size_t read =
        encode_into(text, 0, out.bytes.get(), units, written);
    out.size = written;
    if (read < units) {
      const std::size_t room = 3 * (units - read);
      std::unique_ptr<char[]> wider(new char[written + room]);
      std::memcpy(wider.get(), out.bytes.get(), written);
      out.bytes = std::move(wider);
      std::size_t more = 0;
      encode_into(text, read, out.bytes.get() + written, room, more);
      out.size += more;
    }
    return true;
  }
  val bytes = text;
  if (text.instanceof (val::global("ArrayBuffer"))) {
    bytes = val::global("Uint8Array").new_(text);
  } else if (!val::global("ArrayBuffer").call<bool>("isView", text) ||
             bytes["BYTES_PER_ELEMENT"].as<int>() != 1) {
    return false;
  }
  out.size = bytes["length"].as<std::size_t>();
  out.bytes.reset(new char[out.size + 1]);
  val(emscripten::typed_memory_view(
          out.size, reinterpret_cast<unsigned char*>(out.bytes.get())))
      .call<void>("set", bytes);
  return true;
}

Status not_text() {
  return Status::error(
      Status_code::invalid_argument,
      "The mesh text must be a string, a Uint8Array or an ArrayBuffer.");
}

bool parse_format(const std::string& name, Mesh_format& format) {
  for (const Mesh_format f : {Mesh_format::off, Mesh_format::obj,
                              Mesh_format::ply, Mesh_format::stl}) {
    if (name == format_name(f)) {
      format = f;
      return true;
    }
  }
  return false;
}

Status unknown_format(const std::string& name) {
  return Status::error(Status_code::invalid_argument,
                       "Unknown mesh format \"" + name +
                           "\"; expected \"off\", \"obj\", \"ply\" or "
                           "\"stl\".");
}

/// The format to read `bytes` as: `name`, or with "auto" the core's guess
/// from the content (detect_format).
Status read_format(const std::string& name, std::string_view bytes,
                   Mesh_format& format) {
  if (name == "auto") {
    const Result<Mesh_format> detected = detect_format(bytes);
    format = detected.value;
    return detected.status;
  }
  return parse_format(name, format) ? Status::success() : unknown_format(name);
}

/// Read_options of { repairOrientation?: boolean } (undefined: defaults).
Read_options from_js_read_options(const val& js) {
  Read_options options;
  if (js.isUndefined() || js.isNull()) return options;
  options.repair_orientation = js["repairOrientation"].isTrue();
  return options;
}

/// Bytes the heap can still give: the address space left to grow into plus
/// nothing for the free chunks inside it (kept as slack), minus a margin.
std::size_t available_heap_bytes() {
  const struct mallinfo info = mallinfo();
  const std::size_t in_use = static_cast<unsigned int>(info.uordblks);
  const std::size_t max = emscripten_get_heap_max();
  const std::size_t used = in_use + heap_safety_margin;
  return used < max ? max - used : 1;
}

/// Reads the tables of web/core/rule-set.ts's CompiledRules into `rules`
/// (shape only; check_custom_rules judges the numbers).
Status from_js_rules(const val& js, Custom_rules& rules) {
  const auto bad = [](const std::string& what) {
    return Status::error(Status_code::invalid_argument,
                         "Option rules: " + what + ".");
  };
  if (!js["host"].isString()) return bad("host must be a string");
  rules.host = js["host"].as<std::string>();
  const auto numbers = [&js](const char* key) {
    const val v = js[key];
    if (v.isUndefined() || v.isNull()) return std::vector<double>{};
    return emscripten::convertJSArrayToNumberVector<double>(v);
  };
  const auto fixed = [&](const char* key, double* out, std::size_t n) {
    const std::vector<double> v = numbers(key);
    if (v.empty()) return true;  // keep the default
    if (v.size() != n) return false;
    std::copy(v.begin(), v.end(), out);
    return true;
  };
  const std::vector<double> vertex = numbers("vertex");
  if (vertex.size() % 3 != 0)
    return bad("vertex must hold 3 numbers per valence");
  rules.first_valence =
      js["firstValence"].isNumber() ? js["firstValence"].as<int>() : 3;
  rules.vertex.clear();
  for (std::size_t i = 0; i < vertex.size(); i += 3)
    rules.vertex.push_back({vertex[i], vertex[i + 1], vertex[i + 2]});
  double edge[2] = {rules.edge_end, rules.edge_wing};
  if (!fixed("edge", edge, 2)) return bad("edge must hold 2 numbers");
  rules.edge_end = edge[0];
  rules.edge_wing = edge[1];
  rules.first_degree =
      js["firstDegree"].isNumber() ? js["firstDegree"].as<int>() : 3;
  if (rules.first_degree < 3 || rules.first_degree > 1 << 20)
    return bad("firstDegree must be 3 or more");
  const std::vector<double> corner = numbers("corner");
  rules.corner.clear();
  std::size_t at = 0;
  for (std::size_t k = static_cast<std::size_t>(rules.first_degree);
       at < corner.size(); ++k) {
    if (at + k > corner.size())
      return bad("corner must hold k numbers for each degree k");
    rules.corner.emplace_back(corner.begin() + at, corner.begin() + at + k);
    at += k;
  }
  if (!fixed("borderVertex", rules.border_vertex.data(), 3))
    return bad("borderVertex must hold 3 numbers");
  if (!fixed("borderEdge", rules.border_edge.data(), 4))
    return bad("borderEdge must hold 4 numbers");
  if (!fixed("borderCorner", rules.border_corner.data(), 2))
    return bad("borderCorner must hold 2 numbers");
  return Status::success();
}

/// Reads { scheme, levels, startLevel, triangulate, memoryLimitBytes,
/// smoothBoundary, creaseMethod, boundary, rules, renderBuffers }.
Status from_js_options(const val& js, Subdivide_options& options) {
  if (!js.isUndefined() && !js.isNull()) {
    const val scheme = js["scheme"];
    if (scheme.isString())
      options.scheme = scheme.as<std::string>();
    else if (!scheme.isUndefined())
      return Status::error(Status_code::invalid_argument,
                           "Option scheme must be a string.");
    // Whole numbers in [-1e9, 1e9]. A larger levels is clamped to 1e9: every
    // scheme at least doubles the mesh per step, so the memory check refuses
    // it as it would the original (clamping start_level would change sqrt3's
    // parity, so a larger start_level is refused).
    const auto read_int = [&js](const char* key, int& value, bool clamp_up) {
      const val v = js[key];
      if (v.isUndefined()) return true;
      if (!v.isNumber()) return false;
      const double d = v.as<double>();
      if (!std::isfinite(d) || d != std::floor(d) || d < -1e9) return false;
      if (d > 1e9 && !clamp_up) return false;
      value = static_cast<int>(std::min(d, 1e9));
      return true;
    };
    if (!read_int("levels", options.levels, true))
      return Status::error(Status_code::invalid_argument,
                           "Option levels must be a whole number, 0 or more.");
    if (!read_int("startLevel", options.start_level, false))
      return Status::error(
          Status_code::invalid_argument,
          "Option startLevel must be a whole number from 0 to 1000000000.");
    const val triangulate = js["triangulate"];
    if (!triangulate.isUndefined())
      options.triangulate = triangulate.as<bool>();
    const val render = js["renderBuffers"];
    if (!render.isUndefined()) options.render_buffers = render.as<bool>();
    const val smooth = js["smoothBoundary"];
    if (!smooth.isUndefined()) options.smooth_boundary = smooth.as<bool>();
    const val cgal_hosts = js["cgalHosts"];
    if (!cgal_hosts.isUndefined()) options.cgal_hosts = cgal_hosts.as<bool>();
    const val method = js["creaseMethod"];
    if (!method.isUndefined())
      options.crease_method =
          crease_method_from_js(method, "Option creaseMethod");
    const val boundary = js["boundary"];
    if (!boundary.isUndefined())
      options.boundary = boundary_from_js(boundary, "Option boundary");
    const val rules = js["rules"];
    if (!rules.isUndefined() && !rules.isNull()) {
      const Status s = from_js_rules(rules, options.custom);
      if (!s.ok()) return s;
    }
    const val limit = js["memoryLimitBytes"];
    if (limit.isNumber() && limit.as<double>() > 0)
      options.memory_limit_bytes =
          static_cast<std::size_t>(std::min(limit.as<double>(), 1.8e19));
  }
  const std::size_t available = available_heap_bytes();
  if (options.memory_limit_bytes == 0 || options.memory_limit_bytes > available)
    options.memory_limit_bytes = available;
  return Status::success();
}

/// `text` on one line (messages end up in one CLI error line).
std::string one_line(std::string text) {
  for (char& c : text)
    if (c == '\n' || c == '\r') c = ' ';
  return text;
}

/// CGAL reports a failed check through its error handler (which prints to
/// stderr) and then throws; the exception carries everything, so stay quiet.
void silent_cgal_failure(const char*, const char*, const char*, int,
                         const char*) {}

/// Runs `body`, turning anything thrown into an error object.
template <class Body>
val guarded(Body body) {
  try {
    return body();
  } catch (const Bad_argument& e) {
    return to_js_status(Status::error(Status_code::invalid_argument, e.what()));
  } catch (const std::bad_alloc&) {
    return to_js_status(Status::error(
        Status_code::too_large,
        "Out of memory: the WebAssembly heap could not grow any further."));
  } catch (const CGAL::Failure_exception& e) {
    std::string what = "Internal error: CGAL check failed: " + e.expression();
    if (!e.message().empty()) what += " (" + e.message() + ")";
    return to_js_status(
        Status::error(Status_code::internal_error, one_line(what)));
  } catch (const std::exception& e) {
    return to_js_status(
        Status::error(Status_code::internal_error,
                      one_line(std::string("Internal error: ") + e.what())));
  } catch (...) {
    return to_js_status(Status::error(Status_code::internal_error,
                                      "Internal error: unknown exception."));
  }
}

val js_read_mesh(const val& js_text, const std::string& format_name,
                 const val& js_options) {
  return guarded([&] {
    Js_text text;
    if (!from_js_text(js_text, text)) return to_js_status(not_text());
    Mesh_format format;
    const Status known = read_format(format_name, text.view(), format);
    if (!known.ok()) return to_js_status(known);
    const Result<Mesh_buffers> result = read_mesh(
        text.view(), format, nullptr, from_js_read_options(js_options));
    if (!result.ok()) return to_js_status(result.status);
    val out = ok_object();
    out.set("mesh", to_js_mesh(result.value));
    return out;
  });
}

/// Writes the mesh's text in pieces of at most `max_chunk_bytes`, each
/// handed to `on_chunk` as a Uint8Array copy; `on_chunk` returns false to
/// stop (the result is then still ok: the caller knows why it stopped).
val js_write_mesh(const val& mesh, const std::string& format_name,
                  double max_chunk_bytes, const val& on_chunk,
                  const std::string& comment) {
  return guarded([&] {
    Mesh_format format;
    if (!parse_format(format_name, format))
      return to_js_status(unknown_format(format_name));
    const Mesh_buffers buffers = from_js_mesh(mesh);
    const Status writable = check_writable(buffers);
    if (!writable.ok()) return to_js_status(writable);
    const val uint8_array = val::global("Uint8Array");
    write_mesh_chunks(
        buffers, format, static_cast<std::size_t>(max_chunk_bytes),
        [&](std::string_view chunk) {
          const val copy = uint8_array.new_(
              emscripten::typed_memory_view(chunk.size(), chunk.data()));
          return on_chunk(copy).as<bool>();
        },
        comment);
    return ok_object();
  });
}

val js_subdivide(const val& mesh, const val& js_options) {
  return guarded([&] {
    const Mesh_buffers in = from_js_mesh(mesh);
    Subdivide_options options;
    const Status status = from_js_options(js_options, options);
    if (!status.ok()) return to_js_status(status);
    const Result<Mesh_buffers> result = subdivide_mesh(in, options);
    if (!result.ok()) return to_js_status(result.status);
    val out = ok_object();
    out.set("mesh", to_js_mesh(result.value));
    return out;
  });
}

/// The stencils of the last step of `js_options` (stencils.h), as typed
/// arrays: refined vertex v's parents and weights are [offsets[v],
/// offsets[v + 1]); its origin is kinds[v] (an index into kindNames),
/// elements[v], sizes[v] and ends[2v], ends[2v + 1] (0xffffffff: none).
val js_step_stencils(const val& mesh, const val& js_options) {
  return guarded([&] {
    const Mesh_buffers in = from_js_mesh(mesh);
    Subdivide_options options;
    const Status status = from_js_options(js_options, options);
    if (!status.ok()) return to_js_status(status);
    const Result<Stencil_table> result = step_stencils(in, options);
    if (!result.ok()) return to_js_status(result.status);
    const Stencil_table& t = result.value;
    std::vector<std::uint8_t> kinds;
    std::vector<std::uint32_t> elements, sizes, ends;
    for (const Stencil_origin& o : t.origins) {
      kinds.push_back(static_cast<std::uint8_t>(o.kind));
      elements.push_back(o.element);
      sizes.push_back(o.size);
      ends.insert(ends.end(), {o.ends[0], o.ends[1]});
    }
    val names = val::array();
    for (int k = 0; k < kStencilKinds; ++k)
      names.call<void>(
          "push", std::string(stencil_kind_name(static_cast<Stencil_kind>(k))));
    val formulas = val::object();
    for (const auto& [kind, text] : t.formulas) formulas.set(kind, text);
    val out = ok_object();
    out.set("parentVertices", t.parent_vertices);
    out.set("offsets", to_js_array("Uint32Array", t.offsets));
    out.set("parents", to_js_array("Uint32Array", t.parents));
    out.set("weights", to_js_array("Float64Array", t.weights));
    out.set("kinds", to_js_array("Uint8Array", kinds));
    out.set("elements", to_js_array("Uint32Array", elements));
    out.set("sizes", to_js_array("Uint32Array", sizes));
    out.set("ends", to_js_array("Uint32Array", ends));
    out.set("kindNames", names);
    out.set("formulas", formulas);
    return out;
  });
}

/// compare_meshes (compare.h): the verdict, its reasons and the errors.
val js_compare_meshes(const val& reference, const val& candidate,
                      double relative_tolerance) {
  return guarded([&] {
    const Mesh_comparison c = compare_meshes(
        from_js_mesh(reference), from_js_mesh(candidate), relative_tolerance);
    val reasons = val::array();
    for (const std::string& r : c.reasons) reasons.call<void>("push", r);
    val worst = val::array();
    for (const Vertex_error& e : c.worst) {
      val o = val::object();
      o.set("vertex", e.vertex);
      o.set("reference", e.reference);
      o.set("error", e.error);
      worst.call<void>("push", o);
    }
    val out = ok_object();
    out.set("match", c.match);
    out.set("reasons", reasons);
    out.set("referenceVertices", static_cast<double>(c.vertices[0]));
    out.set("resultVertices", static_cast<double>(c.vertices[1]));
    out.set("referenceFaces", static_cast<double>(c.faces[0]));
    out.set("resultFaces", static_cast<double>(c.faces[1]));
    out.set("matching", c.matching);
    out.set("sameFaces", c.same_faces);
    out.set("tolerance", c.tolerance);
    out.set("diagonal", c.diagonal);
    out.set("maxError", c.max_error);
    out.set("meanError", c.mean_error);
    out.set("worst", worst);
    out.set("matched", to_js_array("Uint32Array", c.matched));
    out.set("errors", to_js_array("Float64Array", c.errors));
    return out;
  });
}

/// hausdorff_distance (hausdorff.h).
val js_hausdorff_distance(const val& a, const val& b, bool vertex_distances) {
  return guarded([&] {
    const Result<Hausdorff_distance> r = hausdorff_distance(
        from_js_mesh(a), from_js_mesh(b), 1e-4, vertex_distances);
    if (!r.ok()) return to_js_status(r.status);
    val out = ok_object();
    out.set("distance", r.value.distance);
    out.set("diagonal", r.value.diagonal);
    out.set("errorBound", r.value.error_bound);
    if (vertex_distances) {
      out.set("aToB", to_js_array("Float64Array", r.value.a_to_b));
      out.set("bToA", to_js_array("Float64Array", r.value.b_to_a));
    }
    return out;
  });
}

/// vertex_curvature (curvature.h): NaN on border vertices.
val js_vertex_curvature(const val& mesh) {
  return guarded([&] {
    const Result<Vertex_curvature> r = vertex_curvature(from_js_mesh(mesh));
    if (!r.ok()) return to_js_status(r.status);
    val out = ok_object();
    out.set("gaussian", to_js_array("Float64Array", r.value.gaussian));
    out.set("mean", to_js_array("Float64Array", r.value.mean));
    out.set("angleDefect", to_js_array("Float64Array", r.value.angle_defect));
    out.set("area", to_js_array("Float64Array", r.value.area));
    out.set("borderVertices", static_cast<double>(r.value.border_vertices));
    return out;
  });
}

val to_js_xyz(const std::array<double, 3>& p) {
  val out = val::array();
  for (double x : p) out.call<void>("push", x);
  return out;
}

/// halfedge_table (halfedges.h): { next, prev, opposite, target, face }.
val js_halfedge_table(const val& mesh) {
  return guarded([&] {
    const Result<Halfedge_table> r = halfedge_table(from_js_mesh(mesh));
    if (!r.ok()) return to_js_status(r.status);
    val out = ok_object();
    out.set("next", to_js_array("Uint32Array", r.value.next));
    out.set("prev", to_js_array("Uint32Array", r.value.prev));
    out.set("opposite", to_js_array("Uint32Array", r.value.opposite));
    out.set("target", to_js_array("Uint32Array", r.value.target));
    out.set("face", to_js_array("Int32Array", r.value.face));
    return out;
  });
}

/// inspect_mesh (inspect.h): the measures and each computation asked for,
/// with its milliseconds.
val js_inspect_mesh(const val& mesh, bool self_intersections, bool sphere,
                    bool hull, bool width, double max_pairs) {
  return guarded([&] {
    Inspect_options o;
    o.self_intersections = self_intersections;
    o.sphere = sphere;
    o.hull = hull;
    o.width = width;
    o.max_pairs = static_cast<std::size_t>(std::max(0.0, max_pairs));
    const Result<Inspection> r = inspect_mesh(from_js_mesh(mesh), o);
    if (!r.ok()) return to_js_status(r.status);
    const Inspection& i = r.value;
    val out = ok_object();
    val m = val::object();
    m.set("area", i.measures.area);
    m.set("volume", i.measures.volume);
    m.set("closed", i.measures.closed);
    m.set("bboxMin", to_js_xyz(i.measures.bbox_min));
    m.set("bboxMax", to_js_xyz(i.measures.bbox_max));
    m.set("diagonal", i.measures.diagonal);
    m.set("ms", i.measures.ms);
    out.set("measures", m);
    if (i.has_self_intersections) {
      val x = val::object();
      x.set("pairs", static_cast<double>(i.self_intersections.pairs));
      x.set("firstPairs",
            to_js_array("Uint32Array", i.self_intersections.first_pairs));
      x.set("faces", to_js_array("Uint32Array", i.self_intersections.faces));
      x.set("ms", i.self_intersections.ms);
      out.set("selfIntersections", x);
    }
    if (i.has_sphere) {
      val x = val::object();
      x.set("center", to_js_xyz(i.sphere.center));
      x.set("radius", i.sphere.radius);
      x.set("ms", i.sphere.ms);
      out.set("sphere", x);
    }
    if (i.has_hull) {
      val x = val::object();
      x.set("vertices", static_cast<double>(i.hull.vertices));
      x.set("edges", static_cast<double>(i.hull.edges));
      x.set("faces", static_cast<double>(i.hull.faces));
      x.set("area", i.hull.area);
      x.set("volume", i.hull.volume);
      x.set("positions", to_js_array("Float64Array", i.hull.positions));
      x.set("triangles", to_js_array("Uint32Array", i.hull.triangles));
      x.set("ms", i.hull.ms);
      out.set("hull", x);
    }
    if (i.has_width) {
      val x = val::object();
      x.set("skipped", i.width.skipped);
      x.set("width", i.width.width);
      x.set("normal", to_js_xyz(i.width.normal));
      val offsets = val::array();
      for (double d : i.width.offsets) offsets.call<void>("push", d);
      x.set("offsets", offsets);
      x.set("ms", i.width.ms);
      out.set("width", x);
    }
    return out;
  });
}

/// A prediction as web/core/mesh.ts's SizePrediction, or its error.
val to_js_prediction(const Result<Size_prediction>& result,
                     const Subdivide_options& options) {
  if (!result.ok()) return to_js_status(result.status);
  val prediction = val::object();
  prediction.set("vertices", static_cast<double>(result.value.vertices));
  prediction.set("edges", static_cast<double>(result.value.edges));
  prediction.set("faces", static_cast<double>(result.value.faces));
  prediction.set("peakBytes", static_cast<double>(result.value.peak_bytes));
  prediction.set("memoryLimitBytes",
                 static_cast<double>(options.memory_limit_bytes));
  val out = ok_object();
  out.set("prediction", prediction);
  return out;
}

val js_predict_size(const val& mesh, const val& js_options) {
  return guarded([&] {
    const Mesh_buffers in = from_js_mesh(mesh);
    Subdivide_options options;
    const Status status = from_js_options(js_options, options);
    if (!status.ok()) return to_js_status(status);
    return to_js_prediction(predict_size(in, options), options);
  });
}

/// predict_size of a closed mesh without tags from its counts
/// (web/core/subdiv-core.ts's predictSizeOfLevel).
val js_predict_size_of_counts(const val& counts, const val& js_options) {
  return guarded([&] {
    Subdivide_options options;
    const Status status = from_js_options(js_options, options);
    if (!status.ok()) return to_js_status(status);
    Closed_mesh_counts c;
    for (auto [name, field] :
         {std::pair{"vertices", &c.vertices}, std::pair{"edges", &c.edges},
          std::pair{"faces", &c.faces}, std::pair{"triangles", &c.triangles},
          std::pair{"controlEdges", &c.control_edges}}) {
      const double x = counts[name].as<double>();
      if (!(x >= 0 && x < 9007199254740992.0) || x != std::floor(x))
        return to_js_status(
            Status::error(Status_code::invalid_argument,
                          std::string("counts: ") + name +
                              " is not a count: " + std::to_string(x)));
      *field = static_cast<std::uint64_t>(x);
    }
    return to_js_prediction(predict_size(c, options), options);
  });
}

val to_js_point(const std::array<double, 3>& p) {
  val out = val::array();
  for (double c : p) out.call<void>("push", c);
  return out;
}

val to_js_facts(const Mesh_facts& f) {
  val facts = val::object();
  facts.set("vertices", static_cast<double>(f.vertices));
  facts.set("edges", static_cast<double>(f.edges));
  facts.set("faces", static_cast<double>(f.faces));
  facts.set("components", static_cast<double>(f.components));
  facts.set("boundaries", static_cast<double>(f.boundaries));
  facts.set("eulerCharacteristic", static_cast<double>(f.euler_characteristic));
  facts.set("genus", static_cast<double>(f.genus));
  facts.set("closed", f.closed);
  facts.set("triangles", static_cast<double>(f.triangles));
  facts.set("quads", static_cast<double>(f.quads));
  facts.set("otherFaces", static_cast<double>(f.other_faces));
  facts.set("bboxMin", to_js_point(f.bbox_min));
  facts.set("bboxMax", to_js_point(f.bbox_max));
  facts.set("controlEdges", static_cast<double>(f.control_edges));
  return facts;
}

/// The parent facts a step carries (refined_facts checks them against the
/// counts, so numbers that are not whole only cost a CGAL pass).
Mesh_facts from_js_facts(const val& js) {
  Mesh_facts f;
  const auto count = [&js](const char* key) {
    const val v = js[key];
    if (!v.isNumber()) return -1.0;
    const double d = v.as<double>();
    return std::isfinite(d) ? d : -1.0;
  };
  const double components = count("components");
  const double boundaries = count("boundaries");
  const double chi = count("eulerCharacteristic");
  if (components >= 0 && components < 1e15)
    f.components = static_cast<std::size_t>(components);
  if (boundaries >= 0 && boundaries < 1e15)
    f.boundaries = static_cast<std::size_t>(boundaries);
  // Without one, a characteristic no mesh has: the counts then disagree.
  f.euler_characteristic =
      js["eulerCharacteristic"].isNumber() && std::abs(chi) < 1e15
          ? static_cast<long>(chi)
          : std::numeric_limits<long>::min();
  return f;
}

/// Hands each render array to JS as a copy, under its name in `out`.
class Js_render_sink : public Render_sink {
 public:
  val out = val::object();
  void floats(Render_array which, const std::vector<float>& v) override {
    out.set(name(which), to_js_array("Float32Array", v));
  }
  void indices(Render_array which,
               const std::vector<std::uint32_t>& v) override {
    out.set(name(which), to_js_array("Uint32Array", v));
  }

 private:
  static const char* name(Render_array which) {
    switch (which) {
      case Render_array::positions:
        return "positions";
      case Render_array::bounding_sphere:
        return "boundingSphere";
      case Render_array::normals:
        return "normals";
      case Render_array::triangles:
        return "triangles";
      case Render_array::triangle_face:
        return "triangleFace";
      case Render_array::edges:
        return "edges";
      case Render_array::border_edges:
        return "borderEdges";
    }
    return "edges";
  }
};

/// apply_euler_op (euler_ops.h): { mesh, facts, valid, halfedge }.
val js_euler_op(const val& mesh, const std::string& op_name, double h,
                double h2) {
  return guarded([&] {
    Euler_request request;
    if (!parse_euler_op(op_name, request.op) || !(h >= 0) || !(h2 >= 0) ||
        h > 4294967295.0 || h2 > 4294967295.0) {
      return to_js_status(
          {Status_code::invalid_argument,
           "Unknown Euler operator \"" + op_name + "\" or halfedge", 0});
    }
    request.h = static_cast<std::uint32_t>(h);
    request.h2 = static_cast<std::uint32_t>(h2);
    const Result<Euler_result> r = apply_euler_op(from_js_mesh(mesh), request);
    if (!r.ok()) return to_js_status(r.status);
    val out = ok_object();
    out.set("mesh", to_js_mesh(r.value.mesh));
    out.set("facts", to_js_facts(r.value.facts));
    out.set("valid", r.value.valid);
    out.set("halfedge", r.value.halfedge);
    return out;
  });
}

/// sqrt3_by_hand (euler_ops.h): { mesh, done, total, last }.
val js_sqrt3_by_hand(const val& mesh, double steps) {
  return guarded([&] {
    const std::size_t n = steps >= 1e15
                              ? SIZE_MAX
                              : static_cast<std::size_t>(std::max(0.0, steps));
    const Result<Sqrt3_walk> r = sqrt3_by_hand(from_js_mesh(mesh), n);
    if (!r.ok()) return to_js_status(r.status);
    val out = ok_object();
    out.set("mesh", to_js_mesh(r.value.mesh));
    out.set("done", static_cast<double>(r.value.done));
    out.set("total", static_cast<double>(r.value.total));
    out.set("last", r.value.last);
    return out;
  });
}

val js_facts(const val& mesh) {
  return guarded([&] {
    const Result<Mesh_facts> result = compute_facts(from_js_mesh(mesh));
    if (!result.ok()) return to_js_status(result.status);
    val out = ok_object();
    out.set("facts", to_js_facts(result.value));
    return out;
  });
}

/// { facts, buffers } of a loaded mesh.
val js_view_mesh(const val& mesh) {
  return guarded([&] {
    Js_render_sink sink;
    const Result<Mesh_facts> facts = view_mesh(from_js_mesh(mesh), sink);
    if (!facts.ok()) return to_js_status(facts.status);
    val out = ok_object();
    out.set("facts", to_js_facts(facts.value));
    out.set("buffers", sink.out);
    return out;
  });
}

/// { mesh, facts, buffers } of OFF/OBJ text (as read_mesh takes it).
val js_read_view(const val& js_text, const std::string& format_name,
                 const val& js_options) {
  return guarded([&] {
    Js_text text;
    if (!from_js_text(js_text, text)) return to_js_status(not_text());
    Mesh_format format;
    const Status known = read_format(format_name, text.view(), format);
    if (!known.ok()) return to_js_status(known);
    Mesh_buffers mesh;
    Js_render_sink sink;
    const Result<Mesh_facts> facts = read_view(
        text.view(), format, mesh, sink, from_js_read_options(js_options));
    if (!facts.ok()) return to_js_status(facts.status);
    val out = ok_object();
    out.set("mesh", to_js_mesh(mesh));
    out.set("facts", to_js_facts(facts.value));
    out.set("buffers", sink.out);
    return out;
  });
}

/// { mesh, facts, buffers } of a step from a mesh whose facts are `parent`.
val js_subdivide_view(const val& mesh, const val& js_options,
                      const val& parent) {
  return guarded([&] {
    Subdivide_options options;
    const Status status = from_js_options(js_options, options);
    if (!status.ok()) return to_js_status(status);
    Mesh_buffers result;
    Js_render_sink sink;
    const Result<Mesh_facts> facts = view_step(
        from_js_mesh(mesh), options, from_js_facts(parent), result, sink);
    if (!facts.ok()) return to_js_status(facts.status);
    val out = ok_object();
    out.set("mesh", to_js_mesh(result));
    out.set("facts", to_js_facts(facts.value));
    out.set("buffers", sink.out);
    return out;
  });
}

/// Checks a rule set's tables (finite weights, stencils summing to 1)
/// without a mesh: the rules panel's instant feedback.
val js_check_rules(const val& js_rules) {
  return guarded([&] {
    Custom_rules rules;
    Status s = from_js_rules(js_rules, rules);
    if (s.ok()) s = check_custom_rules(rules);
    if (!s.ok()) return to_js_status(s);
    return ok_object();
  });
}

val js_scheme_names() {
  return guarded([] {
    val names = val::array();
    for (const std::string& name : scheme_names())
      names.call<void>("push", name);
    val out = ok_object();
    out.set("names", names);
    return out;
  });
}

val js_scheme_info() {
  return guarded([] {
    val hosts = val::array();
    for (const Host_info& h : host_table()) {
      val o = val::object();
      o.set("name", h.name);
      o.set("label", h.label);
      o.set("needsTriangles", h.needs_triangles);
      o.set("keepsControlEdges", h.keeps_control_edges);
      o.set("fast", h.fast);
      o.set("sizeModel", h.size_model);
      hosts.call<void>("push", o);
    }
    val schemes = val::array();
    for (const Scheme_info& s : scheme_table()) {
      val o = val::object();
      o.set("name", s.name);
      o.set("label", s.label);
      o.set("host", s.host.empty() ? val::null() : val(s.host));
      o.set("description", s.description);
      o.set("creases", s.creases);
      schemes.call<void>("push", o);
    }
    val out = ok_object();
    out.set("hosts", hosts);
    out.set("schemes", schemes);
    return out;
  });
}

#ifdef SUBDIVLAB_TEST_HOOKS
// Test hooks: only in the test build of the module (target subdivlab_test,
// which vitest loads), never in the one the app and the CLI ship.

/// Throws what `kind` names ("cgal", "std", "alloc", anything else: an int)
/// inside the same guard as every export: lets the tests prove that such a
/// failure comes back as an error object and that the instance lives on.
val js_throw_for_test(const std::string& kind) {
  return guarded([&]() -> val {
    if (kind == "cgal")
      CGAL::precondition_fail("is_triangle_mesh(mesh)", __FILE__, __LINE__,
                              "raised by throw_for_test");
    if (kind == "std") throw std::runtime_error("raised by throw_for_test");
    if (kind == "alloc") {
      // More than the 4 GB address space: malloc fails, operator new throws.
      // (volatile: a new/delete pair may otherwise be optimised away.)
      static char* volatile sink = nullptr;
      volatile std::size_t bytes = std::size_t{0xFFFFFF00u};
      sink = new char[bytes];
      delete[] sink;
    }
    throw 42;
  });
}
#endif  // SUBDIVLAB_TEST_HOOKS

/// Bytes allocated in the heap right now: the worker reports them
/// (`memory` requests), and the tests check that long sessions and failed
/// calls give everything back.
double js_heap_in_use() {
  return static_cast<double>(static_cast<unsigned int>(mallinfo().uordblks));
}

}  // namespace
}  // namespace subdivlab

EMSCRIPTEN_BINDINGS(subdivlab) {
  CGAL::set_error_handler(&subdivlab::silent_cgal_failure);
  CGAL::set_warning_handler(&subdivlab::silent_cgal_failure);
  emscripten::function("read_mesh", &subdivlab::js_read_mesh);
  emscripten::function("write_mesh", &subdivlab::js_write_mesh);
  emscripten::function("subdivide", &subdivlab::js_subdivide);
  emscripten::function("predict_size", &subdivlab::js_predict_size);
  emscripten::function("predict_size_of_counts",
                       &subdivlab::js_predict_size_of_counts);
  emscripten::function("step_stencils", &subdivlab::js_step_stencils);
  emscripten::function("compare_meshes", &subdivlab::js_compare_meshes);
  emscripten::function("hausdorff_distance", &subdivlab::js_hausdorff_distance);
  emscripten::function("inspect_mesh", &subdivlab::js_inspect_mesh);
  emscripten::function("halfedge_table", &subdivlab::js_halfedge_table);
  emscripten::function("euler_op", &subdivlab::js_euler_op);
  emscripten::function("sqrt3_by_hand", &subdivlab::js_sqrt3_by_hand);
  emscripten::function("vertex_curvature", &subdivlab::js_vertex_curvature);
  emscripten::function("facts", &subdivlab::js_facts);
  emscripten::function("view_mesh", &subdivlab::js_view_mesh);
  emscripten::function("read_view", &subdivlab::js_read_view);
  emscripten::function("subdivide_view", &subdivlab::js_subdivide_view);
  emscripten::function("scheme_names", &subdivlab::js_scheme_names);
  emscripten::function("scheme_info", &subdivlab::js_scheme_info);
  emscripten::function("check_rules", &subdivlab::js_check_rules);
  emscripten::function("heap_in_use", &subdivlab::js_heap_in_use);
#ifdef SUBDIVLAB_TEST_HOOKS
  emscripten::function("throw_for_test", &subdivlab::js_throw_for_test);
#endif
}
