// osd_reference: OpenSubdiv's refinement of a mesh file, level by level, in
// SubdivLab's numbering, as JSON on stdout. The Node tests of the WASM core
// (tests/unit/opensubdiv.test.ts) compare its points index for index; the
// numbering comes from SubdivLab's native core (osd_harness.h), the points
// and the holes from OpenSubdiv.
//
//   osd_reference --scheme catmull-clark|loop --levels N
//                 [--crease-method uniform|chaikin]
//                 [--boundary none|edge|edge-and-corner] FILE.obj|FILE.off
//
// Output: {"levels": [{"positions": [x0, y0, z0, ...], "holes": [[v, ...],
// ...]}, ...]} for levels 1..N; holes as vertex cycles from the smallest.
#include <cstdio>
#include <fstream>
#include <iostream>
#include <iterator>
#include <set>
#include <string>
#include <vector>

#include "core/mesh_io.h"
#include "osd_harness.h"

namespace {

int fail(const std::string& message) {
  std::cerr << "osd_reference: " << message << "\n";
  return 1;
}

}  // namespace

int main(int argc, char** argv) {
  using namespace subdivlab;
  std::string scheme, file, method, boundary;
  int levels = 0;
  for (int i = 1; i < argc; ++i) {
    const std::string arg = argv[i];
    const bool has_value = i + 1 < argc;
    if (arg == "--scheme" && has_value) {
      scheme = argv[++i];
    } else if (arg == "--levels" && has_value) {
      levels = std::stoi(argv[++i]);
    } else if (arg == "--crease-method" && has_value) {
      method = argv[++i];
    } else if (arg == "--boundary" && has_value) {
      boundary = argv[++i];
    } else {
      file = arg;
    }
  }
  if ((scheme != "catmull-clark" && scheme != "loop") || levels < 1 ||
      file.empty())
    return fail("usage: --scheme catmull-clark|loop --levels N FILE");
  const bool loop = scheme == "loop";
  std::ifstream in(file);
  if (!in) return fail("cannot read " + file);
  const std::string text{std::istreambuf_iterator<char>(in),
                         std::istreambuf_iterator<char>()};
  const bool obj = file.size() > 4 && file.substr(file.size() - 4) == ".obj";
  auto read = read_mesh(text, obj ? Mesh_format::obj : Mesh_format::off);
  if (!read.ok()) return fail(read.status.message);
  Mesh_buffers mesh = std::move(read.value);
  if (method == "chaikin") mesh.tags.crease_method = Crease_method::chaikin;
  if (method == "uniform") mesh.tags.crease_method = Crease_method::uniform;
  if (boundary == "none") mesh.tags.boundary = Boundary_interpolation::none;
  if (boundary == "edge")
    mesh.tags.boundary = Boundary_interpolation::edge_only;
  if (boundary == "edge-and-corner")
    mesh.tags.boundary = Boundary_interpolation::edge_and_corner;

  const osd::Run run = osd::refine(mesh, loop, levels);
  if (!run.refiner) return fail("OpenSubdiv refused the mesh");
  std::vector<int> map(mesh.vertex_count());
  for (std::size_t v = 0; v < map.size(); ++v) map[v] = static_cast<int>(v);
  Mesh_buffers parent = mesh;
  std::printf("{\"levels\": [");
  for (int level = 1; level <= levels; ++level) {
    std::string error;
    const Mesh_buffers child = osd::step(parent, loop, error);
    if (!error.empty()) return fail(error);
    std::vector<int> origins =
        osd::child_origins(run, level - 1, parent, child, map, loop, error);
    if (!error.empty()) return fail(error);
    std::printf("%s{\"positions\": [", level > 1 ? ", " : "");
    for (std::size_t v = 0; v < origins.size(); ++v) {
      const osd::Point& p = run.points[level][origins[v]];
      std::printf("%s%.17g, %.17g, %.17g", v > 0 ? ", " : "", p.x, p.y, p.z);
    }
    // OpenSubdiv's holes, in SubdivLab's numbering.
    std::vector<int> ours(run.refiner->GetLevel(level).GetNumVertices(), -1);
    for (std::size_t v = 0; v < origins.size(); ++v)
      ours[origins[v]] = static_cast<int>(v);
    std::set<std::vector<int>> holes;
    const auto& cl = run.refiner->GetLevel(level);
    for (int f = 0; f < cl.GetNumFaces(); ++f) {
      if (!cl.IsFaceHole(f)) continue;
      std::vector<int> face;
      for (const int v : cl.GetFaceVertices(f)) face.push_back(ours[v]);
      holes.insert(osd::cycle(face));
    }
    std::printf("], \"holes\": [");
    bool first = true;
    for (const auto& face : holes) {
      std::printf("%s[", first ? "" : ", ");
      for (std::size_t j = 0; j < face.size(); ++j)
        std::printf("%s%d", j > 0 ? ", " : "", face[j]);
      std::printf("]");
      first = false;
    }
    std::printf("]}");
    map = std::move(origins);
    parent = child;
  }
  std::printf("]}\n");
  return 0;
}
