// OpenSubdiv side of `npm run bench`: the same work as subdiv_bench_native
// (build the topology from face lists, refine uniformly, compute the new
// positions) with OpenSubdiv's Far layer (Debian's libosd-dev), so the
// benchmark can give SubdivLab's time as a ratio to OpenSubdiv's in the same
// run. Prints one JSON object per scheme (scheme, faces, median_ms, runs_ms).
// Usage: subdiv_bench_osd MESH.off RUNS LEVELS SCHEME...   (loop,
// catmull-clark)
#include <opensubdiv/far/primvarRefiner.h>
#include <opensubdiv/far/topologyDescriptor.h>
#include <opensubdiv/far/topologyRefinerFactory.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <iostream>
#include <memory>
#include <sstream>
#include <string>
#include <vector>

#include "bench_report.h"
#include "core/mesh_io.h"

namespace {

using namespace OpenSubdiv;

/** A position as Far::PrimvarRefiner interpolates it. */
struct Point {
  double x = 0, y = 0, z = 0;
  void Clear() { x = y = z = 0; }
  void AddWithWeight(const Point& p, float w) {
    x += w * p.x;
    y += w * p.y;
    z += w * p.z;
  }
};

/** Refines `levels` times and returns the number of faces of the last level. */
std::size_t refine(const subdivlab::Mesh_buffers& mesh, Sdc::SchemeType type,
                   int levels) {
  std::vector<int> sizes(mesh.face_sizes.begin(), mesh.face_sizes.end());
  std::vector<Far::Index> indices(mesh.face_indices.begin(),
                                  mesh.face_indices.end());
  Far::TopologyDescriptor desc;
  desc.numVertices = static_cast<int>(mesh.positions.size() / 3);
  desc.numFaces = static_cast<int>(sizes.size());
  desc.numVertsPerFace = sizes.data();
  desc.vertIndicesPerFace = indices.data();
  Sdc::Options sdc;
  // Smooth borders (cubic B-spline), as CGAL's and SubdivLab's border rules.
  sdc.SetVtxBoundaryInterpolation(Sdc::Options::VTX_BOUNDARY_EDGE_ONLY);
  using Factory = Far::TopologyRefinerFactory<Far::TopologyDescriptor>;
  std::unique_ptr<Far::TopologyRefiner> refiner(
      Factory::Create(desc, Factory::Options(type, sdc)));
  // Refused topology (e.g. Loop on polygons other than triangles): nothing to
  // time.
  if (!refiner) return 0;
  refiner->RefineUniform(Far::TopologyRefiner::UniformOptions(levels));

  std::vector<Point> points(refiner->GetNumVerticesTotal());
  for (int v = 0; v < desc.numVertices; ++v)
    points[v] = {mesh.positions[3 * v], mesh.positions[3 * v + 1],
                 mesh.positions[3 * v + 2]};
  Far::PrimvarRefiner primvar(*refiner);
  Point* src = points.data();
  for (int level = 1; level <= levels; ++level) {
    Point* dst = src + refiner->GetLevel(level - 1).GetNumVertices();
    primvar.Interpolate(level, src, dst);
    src = dst;
  }
  return static_cast<std::size_t>(refiner->GetLevel(levels).GetNumFaces());
}

}  // namespace

int main(int argc, char** argv) {
  if (argc < 5) {
    std::cerr << "usage: subdiv_bench_osd MESH.off RUNS LEVELS SCHEME...\n";
    return 2;
  }
  const std::string path = argv[1];
  const int runs = std::max(1, std::atoi(argv[2]));
  const int levels = std::max(1, std::atoi(argv[3]));
  std::ifstream file(path, std::ios::binary);
  std::stringstream text;
  text << file.rdbuf();
  const auto mesh =
      subdivlab::read_mesh(text.str(), subdivlab::Mesh_format::off);
  if (!file || !mesh.ok()) {
    std::cerr << "error: " << path << ": cannot read the mesh\n";
    return 1;
  }
  for (int i = 4; i < argc; ++i) {
    const std::string scheme = argv[i];
    Sdc::SchemeType type;
    if (scheme == "loop") {
      type = Sdc::SCHEME_LOOP;
    } else if (scheme == "catmull-clark") {
      type = Sdc::SCHEME_CATMARK;
    } else {
      std::cerr << "error: OpenSubdiv has no scheme " << scheme << "\n";
      return 2;
    }
    std::vector<double> times;
    std::size_t faces = 0;
    for (int r = 0; r <= runs; ++r) {
      const auto start = std::chrono::steady_clock::now();
      faces = refine(mesh.value, type, levels);
      if (faces == 0) {
        std::cerr << "error: OpenSubdiv refused the mesh for " << scheme
                  << " (Loop needs triangles)\n";
        return 1;
      }
      const auto stop = std::chrono::steady_clock::now();
      if (r > 0)
        times.push_back(
            std::chrono::duration<double, std::milli>(stop - start).count());
    }
    subdivlab_bench::print_result(scheme, faces, times);
  }
  return 0;
}
