// Native side of `npm run bench`'s Inspect table: each of CGAL's geometry
// computations (core/inspect.h) alone on a mesh, or on its level K of Loop
// (triangulated first), as the tutorial's table times them. Prints one JSON
// object: the mesh's counts and, per computation, its figure and the core's
// own milliseconds (one run each: the width alone takes seconds).
// Usage: subdiv_bench_inspect MESH.off LOOP_LEVELS
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <iostream>
#include <sstream>
#include <string>

#include "core/inspect.h"
#include "core/mesh_io.h"
#include "core/subdivide.h"

int main(int argc, char** argv) {
  using namespace subdivlab;
  if (argc != 3) {
    std::cerr << "usage: subdiv_bench_inspect MESH.off LOOP_LEVELS\n";
    return 2;
  }
  std::ifstream file(argv[1], std::ios::binary);
  if (!file) {
    std::cerr << "error: " << argv[1] << ": cannot read\n";
    return 1;
  }
  std::stringstream text;
  text << file.rdbuf();
  Result<Mesh_buffers> mesh = read_mesh(text.str(), Mesh_format::off);
  if (!mesh.ok()) {
    std::cerr << "error: " << argv[1] << ": " << mesh.status.message << "\n";
    return 1;
  }
  Mesh_buffers in = mesh.value;
  const int levels = std::atoi(argv[2]);
  if (levels > 0) {
    Subdivide_options o;
    o.scheme = "loop";
    o.levels = levels;
    o.triangulate = true;
    in = subdivide_mesh(in, o).value;
  }
  std::printf("{\"vertices\":%zu,\"faces\":%zu,\"rows\":[",
              in.positions.size() / 3, in.face_count());
  const char* names[] = {"self-intersections", "sphere", "hull", "width"};
  for (int k = 0; k < 4; ++k) {
    Inspect_options o;
    o.self_intersections = k == 0;
    o.sphere = k == 1;
    o.hull = k == 2;
    o.width = k == 3;
    const Result<Inspection> r = inspect_mesh(in, o);
    if (!r.ok()) {
      std::cerr << "error: " << r.status.message << "\n";
      return 1;
    }
    const Inspection& i = r.value;
    double figure = 0, ms = 0;
    bool skipped = false;
    if (k == 0) {
      figure = static_cast<double>(i.self_intersections.pairs);
      ms = i.self_intersections.ms;
    } else if (k == 1) {
      figure = i.sphere.radius;
      ms = i.sphere.ms;
    } else if (k == 2) {
      figure = static_cast<double>(i.hull.vertices);
      ms = i.hull.ms;
    } else {
      figure = i.width.width;
      ms = i.width.ms;
      skipped = i.width.skipped;
    }
    std::printf(
        "%s{\"computation\":\"%s\",\"figure\":%.17g,\"ms\":%.3f,"
        "\"skipped\":%s}",
        k ? "," : "", names[k], figure, ms, skipped ? "true" : "false");
  }
  std::printf("]}\n");
  return 0;
}
