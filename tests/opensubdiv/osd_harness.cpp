#include "osd_harness.h"

#include <opensubdiv/far/primvarRefiner.h>
#include <opensubdiv/far/topologyDescriptor.h>
#include <opensubdiv/far/topologyRefinerFactory.h>

#include <algorithm>
#include <iterator>
#include <map>

#include "core/subdivide.h"

namespace subdivlab::osd {

using namespace OpenSubdiv;

Run refine(const Mesh_buffers& mesh, bool loop, int levels) {
  std::vector<int> sizes(mesh.face_sizes.begin(), mesh.face_sizes.end());
  std::vector<Far::Index> indices(mesh.face_indices.begin(),
                                  mesh.face_indices.end());
  std::vector<Far::Index> creases(mesh.tags.crease_edges.begin(),
                                  mesh.tags.crease_edges.end());
  std::vector<Far::Index> corners(mesh.tags.corner_vertices.begin(),
                                  mesh.tags.corner_vertices.end());
  std::vector<Far::Index> holes(mesh.tags.holes.begin(),
                                mesh.tags.holes.end());
  Far::TopologyDescriptor desc;
  desc.numVertices = static_cast<int>(mesh.vertex_count());
  desc.numFaces = static_cast<int>(sizes.size());
  desc.numVertsPerFace = sizes.data();
  desc.vertIndicesPerFace = indices.data();
  desc.numCreases = static_cast<int>(mesh.tags.crease_sharpness.size());
  desc.creaseVertexIndexPairs = creases.data();
  desc.creaseWeights = mesh.tags.crease_sharpness.data();
  desc.numCorners = static_cast<int>(corners.size());
  desc.cornerVertexIndices = corners.data();
  desc.cornerWeights = mesh.tags.corner_sharpness.data();
  desc.numHoles = static_cast<int>(holes.size());
  desc.holeIndices = holes.data();
  Sdc::Options sdc;
  switch (mesh.tags.boundary) {
    case Boundary_interpolation::edge_only:
      sdc.SetVtxBoundaryInterpolation(Sdc::Options::VTX_BOUNDARY_EDGE_ONLY);
      break;
    case Boundary_interpolation::edge_and_corner:
      sdc.SetVtxBoundaryInterpolation(
          Sdc::Options::VTX_BOUNDARY_EDGE_AND_CORNER);
      break;
    case Boundary_interpolation::none:
      sdc.SetVtxBoundaryInterpolation(Sdc::Options::VTX_BOUNDARY_NONE);
      break;
  }
  sdc.SetCreasingMethod(mesh.tags.crease_method == Crease_method::chaikin
                            ? Sdc::Options::CREASE_CHAIKIN
                            : Sdc::Options::CREASE_UNIFORM);
  using Factory = Far::TopologyRefinerFactory<Far::TopologyDescriptor>;
  Run run;
  run.refiner.reset(Factory::Create(
      desc, Factory::Options(loop ? Sdc::SCHEME_LOOP : Sdc::SCHEME_CATMARK,
                             sdc)));
  if (!run.refiner) return run;
  Far::TopologyRefiner::UniformOptions options(levels);
  options.fullTopologyInLastLevel = true;
  run.refiner->RefineUniform(options);
  run.points.resize(levels + 1);
  run.points[0].resize(mesh.vertex_count());
  for (std::size_t v = 0; v < mesh.vertex_count(); ++v)
    run.points[0][v] = {mesh.positions[3 * v], mesh.positions[3 * v + 1],
                        mesh.positions[3 * v + 2]};
  Far::PrimvarRefinerReal<double> primvar(*run.refiner);
  for (int level = 1; level <= levels; ++level) {
    run.points[level].resize(run.refiner->GetLevel(level).GetNumVertices());
    const Point* src = run.points[level - 1].data();
    Point* dst = run.points[level].data();
    primvar.Interpolate(level, src, dst);
  }
  return run;
}

Mesh_buffers step(const Mesh_buffers& in, bool loop, std::string& error) {
  Subdivide_options options;
  options.scheme = loop ? "loop" : "catmull-clark";
  options.levels = 1;
  auto result = subdivide_mesh(in, options);
  if (!result.ok()) error = result.status.message;
  return std::move(result.value);
}

std::set<std::pair<std::uint32_t, std::uint32_t>> edges_of(
    const Mesh_buffers& m) {
  std::set<std::pair<std::uint32_t, std::uint32_t>> edges;
  std::size_t o = 0;
  for (std::uint32_t k : m.face_sizes) {
    for (std::uint32_t j = 0; j < k; ++j) {
      const std::uint32_t a = m.face_indices[o + j],
                          b = m.face_indices[o + (j + 1) % k];
      edges.insert({std::min(a, b), std::max(a, b)});
    }
    o += k;
  }
  return edges;
}

std::vector<int> cycle(std::vector<int> face) {
  std::rotate(face.begin(), std::min_element(face.begin(), face.end()),
              face.end());
  return face;
}

std::vector<int> child_origins(const Run& run, int parent_level,
                               const Mesh_buffers& parent,
                               const Mesh_buffers& child,
                               const std::vector<int>& map, bool loop,
                               std::string& error) {
  const Far::TopologyLevel& pl = run.refiner->GetLevel(parent_level);
  std::vector<int> origins(child.vertex_count(), -1);
  const auto V = static_cast<std::uint32_t>(parent.vertex_count());
  for (std::uint32_t v = 0; v < V; ++v)
    origins[v] = pl.GetVertexChildVertex(map[v]);
  std::vector<std::set<std::uint32_t>> around(child.vertex_count());
  for (const auto& [a, b] : edges_of(child)) {
    around[a].insert(b);
    around[b].insert(a);
  }
  const auto edges = edges_of(parent);
  for (const auto& [a, b] : edges) {
    std::vector<std::uint32_t> common;
    std::set_intersection(around[a].begin(), around[a].end(),
                          around[b].begin(), around[b].end(),
                          std::back_inserter(common));
    const Far::Index e = pl.FindEdge(map[a], map[b]);
    if (common.size() != 1 || e == Far::INDEX_INVALID) {
      error = "edge " + std::to_string(a) + "-" + std::to_string(b) +
              " has no single edge point";
      return {};
    }
    origins[common[0]] = pl.GetEdgeChildVertex(e);
  }
  if (!loop) {
    // Face points: V + E + f on SubdivLab's side; OpenSubdiv's face found
    // by its vertices.
    std::map<std::vector<int>, int> osd_faces;
    for (int f = 0; f < pl.GetNumFaces(); ++f) {
      const Far::ConstIndexArray fv = pl.GetFaceVertices(f);
      std::vector<int> key(fv.begin(), fv.end());
      std::sort(key.begin(), key.end());
      osd_faces[key] = f;
    }
    std::size_t o = 0;
    const auto E = static_cast<std::uint32_t>(edges.size());
    for (std::uint32_t f = 0; f < parent.face_count(); ++f) {
      std::vector<int> key;
      for (std::uint32_t j = 0; j < parent.face_sizes[f]; ++j)
        key.push_back(map[parent.face_indices[o + j]]);
      o += parent.face_sizes[f];
      std::sort(key.begin(), key.end());
      const auto found = osd_faces.find(key);
      if (found == osd_faces.end()) {
        error = "face " + std::to_string(f) + " is not OpenSubdiv's";
        return {};
      }
      origins[V + E + f] = pl.GetFaceChildVertex(found->second);
    }
  }
  for (std::size_t v = 0; v < origins.size(); ++v) {
    if (origins[v] < 0) {
      error = "vertex " + std::to_string(v) + " has no origin";
      return {};
    }
  }
  return origins;
}

}  // namespace subdivlab::osd
