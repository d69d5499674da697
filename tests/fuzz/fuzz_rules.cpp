// Custom rules: a rule set derived from the bytes as the bindings'
// from_js_rules fills one from the rules panel's tables (a host, a first
// valence and vertex weights per valence, edge weights, a first degree and
// a corner row per degree, border weights), often from a preset or with
// stencils that sum to 1 so that the checks pass, then changed here and
// there (another weight, NaN, infinities, 1e300, any first valence).
// check_custom_rules judges it; an accepted set runs two levels of
// `custom` on small closed and open meshes of quads, triangles and mixed
// faces (check_custom_rules_cover first, as subdivide does), on the fast
// hosts and on CGAL's, and its step on a Surface_mesh
// (custom_subdivision_step). What the headers promise:
//   - sane statuses (no internal_error, no too_large on tiny meshes);
//   - a result is valid with predict_size's counts (require_result);
//   - the fast hosts and CGAL's agree (same verdict; same result);
//   - custom_subdivision_step leaves a valid polygon mesh.

#include <CGAL/boost/graph/helpers.h>
#include <fuzzer/FuzzedDataProvider.h>

#include <limits>
#include <string>
#include <vector>

#include "core/custom_rules.h"
#include "core/mesh_build.h"
#include "core/subdivide.h"
#include "fuzz_targets.h"

namespace subdivlab::fuzz {
namespace {

/// Small meshes: closed quads (valence 3), open quads (one interior vertex
/// of valence 4), closed triangles (valence 4), an open fan (valence 6),
/// and an open mix of triangles, quads and a pentagon.
constexpr const char* kMeshes[] = {
    "OFF\n8 6 0\n-1 -1 -1\n1 -1 -1\n-1 1 -1\n1 1 -1\n-1 -1 1\n1 -1 1\n"
    "-1 1 1\n1 1 1\n4 1 0 2 3\n4 2 0 4 6\n4 3 2 6 7\n4 4 0 1 5\n"
    "4 5 1 3 7\n4 6 4 5 7\n",
    "OFF\n9 4 0\n0 0 0\n1 0 0\n2 0 0\n0 1 0\n1 1 0.5\n2 1 0\n0 2 0\n"
    "1 2 0\n2 2 0\n4 0 1 4 3\n4 1 2 5 4\n4 3 4 7 6\n4 4 5 8 7\n",
    "OFF\n6 8 0\n1 0 0\n-1 0 0\n0 1 0\n0 -1 0\n0 0 1\n0 0 -1\n3 2 0 5\n"
    "3 2 1 4\n3 3 0 4\n3 3 1 5\n3 4 0 2\n3 4 1 3\n3 5 0 3\n3 5 1 2\n",
    "OFF\n7 6 0\n0 0 0.25\n1 0 0\n0.5 0.875 0\n-0.5 0.875 0\n-1 0 0\n"
    "-0.5 -0.875 0\n0.5 -0.875 0\n3 0 1 2\n3 0 2 3\n3 0 3 4\n3 0 4 5\n"
    "3 0 5 6\n3 0 6 1\n",
    "OFF\n13 9 0\n0 0 0\n1 0 0\n2 0 0\n3 0 0\n0 1 0\n1 1 0\n2 1 0\n3 1 0\n"
    "0 2 0\n1 2 0\n2 2 0\n3 2 0\n1.5 2.25 0\n4 0 1 5 4\n3 1 2 6\n3 1 6 5\n"
    "4 2 3 7 6\n3 4 5 9\n3 4 9 8\n5 5 6 10 12 9\n3 6 7 11\n3 6 11 10\n",
};

const std::vector<Mesh_buffers>& meshes() {
  static const std::vector<Mesh_buffers> all = [] {
    std::vector<Mesh_buffers> v;
    for (const char* text : kMeshes) {
      Result<Mesh_buffers> r = read_mesh(text, Mesh_format::off);
      require(r.ok(), "a rules mesh does not read", r.status.message);
      v.push_back(std::move(r.value));
    }
    return v;
  }();
  return all;
}

double weight(FuzzedDataProvider& in) {
  constexpr double kWeights[] = {0,
                                 1,
                                 0.5,
                                 0.25,
                                 0.125,
                                 0.0625,
                                 0.375,
                                 0.75,
                                 -0.0625,
                                 2,
                                 -1,
                                 1e300,
                                 -1e300,
                                 1e-300,
                                 1.0 / 3,
                                 0.6,
                                 0.1,
                                 std::numeric_limits<double>::quiet_NaN(),
                                 std::numeric_limits<double>::infinity()};
  const int pick =
      in.ConsumeIntegralInRange<int>(0, static_cast<int>(std::size(kWeights)));
  if (pick == static_cast<int>(std::size(kWeights)))
    return in.ConsumeFloatingPoint<double>();
  return kWeights[pick];
}

int any_int(FuzzedDataProvider& in, int low, int high) {
  return in.ConsumeIntegralInRange<int>(0, 15) == 0
             ? in.ConsumeIntegral<int>()
             : in.ConsumeIntegralInRange<int>(low, high);
}

Custom_rules rules_from(FuzzedDataProvider& in) {
  constexpr const char* kHosts[] = {"pqq", "ptq", "dqq", "sqrt3"};
  constexpr const char* kPresets[] = {
      "catmull-clark", "loop", "doo-sabin", "sqrt3", "linear", "improved-loop"};
  Custom_rules r;
  if (in.ConsumeBool()) {
    r = custom_rules_preset(
        kPresets[in.ConsumeIntegralInRange<int>(0, std::size(kPresets) - 1)],
        // The tables grow with the largest valence: a few are enough.
        in.ConsumeIntegralInRange<int>(-1, 10));
  } else {
    r.host = in.ConsumeIntegralInRange<int>(0, 31) == 0
                 ? in.ConsumeRandomLengthString(8)
                 : kHosts[in.ConsumeIntegralInRange<int>(0, 3)];
    const bool balanced = in.ConsumeIntegralInRange<int>(0, 7) != 0;
    r.first_valence = any_int(in, 1, 7);
    const int valences = in.ConsumeIntegralInRange<int>(0, 6);
    for (int i = 0; i < valences; ++i) {
      Vertex_weights w;
      const double n = static_cast<double>(r.first_valence) + i;
      w.neighbour = weight(in);
      w.face = r.host == "pqq" || !balanced ? weight(in) : 0.0;
      w.self = balanced ? 1.0 - n * (w.neighbour + w.face) : weight(in);
      r.vertex.push_back(w);
    }
    r.edge_end = weight(in);
    r.edge_wing = balanced ? (1.0 - 2.0 * r.edge_end) / 2.0 : weight(in);
    r.first_degree = in.ConsumeIntegralInRange<int>(0, 15) == 0
                         ? 1 << 20
                         : in.ConsumeIntegralInRange<int>(3, 7);
    const int degrees = in.ConsumeIntegralInRange<int>(0, 4);
    for (int d = 0; d < degrees && r.first_degree < 64; ++d) {
      std::vector<double> row(static_cast<std::size_t>(r.first_degree + d));
      double rest = 1.0;
      for (std::size_t j = 1; j < row.size(); ++j) rest -= row[j] = weight(in);
      row[0] = balanced ? rest : weight(in);
      r.corner.push_back(row);
    }
    const double a = weight(in), b = weight(in);
    r.border_vertex = {a, balanced ? 1.0 - 2.0 * a : weight(in), a};
    r.border_edge = {-b, 0.5 + b, balanced ? 0.5 + b : weight(in), -b};
    const double c = weight(in);
    r.border_corner = {c, balanced ? 1.0 - c : weight(in)};
  }
  // A change here and there: a weight the checks must judge.
  const int changes = in.ConsumeIntegralInRange<int>(0, 2);
  for (int i = 0; i < changes; ++i) {
    switch (in.ConsumeIntegralInRange<int>(0, 5)) {
      case 0:
        if (!r.vertex.empty())
          r.vertex[in.ConsumeIntegralInRange<std::size_t>(0,
                                                          r.vertex.size() - 1)]
              .neighbour = weight(in);
        break;
      case 1:
        r.edge_wing = weight(in);
        break;
      case 2:
        if (!r.corner.empty()) r.corner.back().back() = weight(in);
        break;
      case 3:
        r.border_edge[in.ConsumeIntegralInRange<int>(0, 3)] = weight(in);
        break;
      case 4:
        r.first_valence = any_int(in, 0, 8);
        break;
      default:
        if (!r.vertex.empty()) r.vertex.pop_back();
        break;
    }
  }
  return r;
}

}  // namespace

void fuzz_rules(const std::uint8_t* data, std::size_t size) {
  FuzzedDataProvider in(data, size);
  const Custom_rules rules = rules_from(in);
  const Status checked = check_custom_rules(rules);
  require_sane_status(checked, "check_custom_rules");
  if (!checked.ok()) {
    require(checked.code == Status_code::invalid_argument,
            "check_custom_rules refuses other than invalid_argument",
            checked.message);
    return;
  }
  const bool triangulate = in.ConsumeBool();
  for (std::size_t m = 0; m < meshes().size(); ++m) {
    const Mesh_buffers& buffers = meshes()[m];
    const std::string what = rules.host + " on mesh " + std::to_string(m);
    Mesh mesh;
    require(build_mesh(buffers, mesh).ok(), "a rules mesh does not build");
    const Status cover = check_custom_rules_cover(rules, mesh);
    require_sane_status(cover, "check_custom_rules_cover");

    Subdivide_options o;
    o.scheme = "custom";
    o.custom = rules;
    o.levels = 2;
    o.triangulate = triangulate;
    const Result<Mesh_buffers> fast = subdivide_mesh(buffers, o);
    require_sane_status(fast.status, "subdivide_mesh (custom)");
    require(fast.status.code != Status_code::too_large,
            "too_large on a tiny mesh", what + ": " + fast.status.message);
    if (fast.ok()) require_result(buffers, o, fast.value, what);
    o.cgal_hosts = true;
    const Result<Mesh_buffers> cgal = subdivide_mesh(buffers, o);
    require_sane_status(cgal.status, "subdivide_mesh (custom, CGAL's hosts)");
    // Weights near the largest double overflow in one order of summing and
    // not in the other (fuzz_schemes): only then may the verdicts differ.
    const bool overflow =
        fast.status.message.find("overflows") != std::string::npos ||
        cgal.status.message.find("overflows") != std::string::npos;
    require(cgal.status.code == fast.status.code || overflow,
            "the fast hosts and CGAL's disagree on custom rules",
            what + ": " + fast.status.message + " | " + cgal.status.message);
    if (fast.ok() && cgal.ok())
      require(same_result(fast.value, cgal.value),
              "the fast hosts differ from CGAL's on custom rules", what);

    const bool triangles =
        buffers.face_indices.size() == 3 * buffers.face_count();
    if (!cover.ok() ||
        (!triangles && (rules.host == "ptq" || rules.host == "sqrt3")))
      continue;
    custom_subdivision_step(mesh, rules, 0);
    require(CGAL::is_valid_polygon_mesh(mesh),
            "custom_subdivision_step left an invalid mesh", what);
  }
}

}  // namespace subdivlab::fuzz
