// Validation, presets and the host dispatch of custom rule sets.
#include "custom_rules.h"

#include <CGAL/Subdivision_method_3/internal/subdivision_hosts_impl_3.h>
#include <CGAL/boost/graph/helpers.h>

#include <cmath>
#include <cstdio>
#include <string>

#include "dqq_border_3.h"
#include "file_kind.h"
#include "refine/dual_masks.h"
#include "refine/primal_masks.h"
#include "table_masks_3.h"

namespace subdivlab {
namespace {

constexpr double kSumTolerance = 1e-9;

Status refuse(const std::string& what) {
  return Status::error(Status_code::invalid_argument, "custom rules: " + what);
}

std::string number(double x) {
  if (std::isnan(x)) return "nan";  // whatever its sign bit
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.12g", x);
  return buf;
}

/// `where` reads like "the vertex rule at valence 5".
Status check_stencil(const std::string& where, const double* w,
                     std::size_t count, const double* multiplicity = nullptr) {
  double sum = 0.0;
  for (std::size_t i = 0; i < count; ++i) {
    if (!std::isfinite(w[i]))
      return refuse(where + " has a weight that is not finite (" +
                    number(w[i]) + ")");
    sum += (multiplicity ? multiplicity[i] : 1.0) * w[i];
  }
  if (std::abs(sum - 1.0) > kSumTolerance)
    return refuse(where + " sums to " + number(sum) + ", not 1");
  return Status::success();
}

bool known_host(const std::string& h) {
  return h == "pqq" || h == "ptq" || h == "dqq" || h == "sqrt3";
}

}  // namespace

Status check_custom_rules(const Custom_rules& r) {
  if (!known_host(r.host))
    return refuse("unknown host \"" + detail::printable(r.host) +
                  "\" (expected pqq, ptq, dqq or sqrt3)");

  if (r.host == "dqq") {
    if (r.first_degree < 3)
      return refuse("the corner table must start at degree 3 or more");
    if (r.corner.empty())
      return refuse("the corner rule has no weights (empty table)");
    for (std::size_t i = 0; i < r.corner.size(); ++i) {
      const std::size_t k = static_cast<std::size_t>(r.first_degree) + i;
      const std::string where =
          "the corner rule at degree " + std::to_string(k);
      if (r.corner[i].size() != k)
        return refuse(where + " has " + std::to_string(r.corner[i].size()) +
                      " weights, not " + std::to_string(k));
      Status s = check_stencil(where, r.corner[i].data(), k);
      if (!s.ok()) return s;
    }
    return check_stencil("the border corner rule", r.border_corner.data(), 2);
  }

  if (r.first_valence < 1)
    return refuse("the vertex table must start at valence 1 or more");
  if (r.vertex.empty())
    return refuse("the vertex rule has no weights (empty table)");
  const bool with_faces = r.host == "pqq";
  for (std::size_t i = 0; i < r.vertex.size(); ++i) {
    const std::size_t n = static_cast<std::size_t>(r.first_valence) + i;
    const std::string where = "the vertex rule at valence " + std::to_string(n);
    const Vertex_weights& w = r.vertex[i];
    if (!with_faces && w.face != 0.0)
      return refuse(where + " has a face weight (" + number(w.face) +
                    "), which the " + r.host +
                    " host does not use; it must be 0");
    const double weights[3] = {w.self, w.neighbour, w.face};
    const double mult[3] = {1.0, double(n), double(n)};
    Status s = check_stencil(where, weights, 3, mult);
    if (!s.ok()) return s;
  }
  if (r.host != "sqrt3") {
    const double weights[2] = {r.edge_end, r.edge_wing};
    const double mult[2] = {2.0, 2.0};
    Status s = check_stencil("the edge rule", weights, 2, mult);
    if (!s.ok()) return s;
  }
  Status s = check_stencil("the border vertex rule", r.border_vertex.data(), 3);
  if (!s.ok()) return s;
  return check_stencil("the border edge rule", r.border_edge.data(), 4);
}

Status check_custom_rules_cover(const Custom_rules& r, const Mesh& mesh) {
  if (r.host == "dqq") {
    const std::size_t first = static_cast<std::size_t>(r.first_degree);
    const std::size_t last = first + r.corner.size() - 1;
    for (Mesh::Face_index f : mesh.faces()) {
      const std::size_t k = mesh.degree(f);
      if (k < first || k > last) return custom_rules_degree_refusal(r, k);
    }
    return Status::success();
  }
  const std::size_t first = static_cast<std::size_t>(r.first_valence);
  const std::size_t last = first + r.vertex.size() - 1;
  for (Mesh::Vertex_index v : mesh.vertices()) {
    if (mesh.is_border(v, /*check_all_incident_halfedges=*/true)) continue;
    const std::size_t n = mesh.degree(v);
    if (n < first || n > last) return custom_rules_valence_refusal(r, n);
  }
  return Status::success();
}

Status custom_rules_valence_refusal(const Custom_rules& r, std::size_t n) {
  const std::size_t first = static_cast<std::size_t>(r.first_valence);
  const std::size_t last = first + r.vertex.size() - 1;
  return refuse("the vertex rule has no weights for valence " +
                std::to_string(n) + " (the table covers valences " +
                std::to_string(first) + " to " + std::to_string(last) + ")");
}

Status custom_rules_degree_refusal(const Custom_rules& r, std::size_t k) {
  const std::size_t first = static_cast<std::size_t>(r.first_degree);
  const std::size_t last = first + r.corner.size() - 1;
  return refuse("the corner rule has no weights for faces of degree " +
                std::to_string(k) + " (the table covers degrees " +
                std::to_string(first) + " to " + std::to_string(last) + ")");
}

Custom_rules custom_rules_preset(const std::string& name, int max_valence) {
  Custom_rules r;
  if (max_valence < 3) max_valence = 3;
  auto for_valences = [&](auto weights) {
    r.first_valence = 3;
    for (int n = 3; n <= max_valence; ++n)
      r.vertex.push_back(weights(double(n)));
  };
  if (name == "catmull-clark") {
    // The weights of the fast hosts' masks (refine/primal_masks.h).
    r.host = "pqq";
    for_valences(refine::catmull_clark_vertex_weights);
    r.edge_end = 0.25;
    r.edge_wing = 0.25;
  } else if (name == "loop" || name == "improved-loop") {
    r.host = "ptq";
    const bool improved = name == "improved-loop";
    for_valences([&](double n) {
      if (!improved || n == 6) return refine::loop_vertex_weights(n);
      double beta;  // weight of each neighbour
      if (n == 3) {
        // CGAL's Customized_subdivision example, verbatim (6.283 included).
        beta = (5.0 / 8.0 - std::sqrt(3 + 2 * std::cos(6.283 / n)) / 64.0) / n;
      } else {
        beta = 3.0 / 8.0 / n;  // Warren
      }
      return Vertex_weights{1 - n * beta, beta, 0.0};
    });
    r.edge_end = 3.0 / 8.0;
    r.edge_wing = 1.0 / 8.0;
  } else if (name == "doo-sabin") {
    // The weights of the fast host's mask (refine/dual_masks.h).
    r.host = "dqq";
    r.first_degree = 3;
    for (int k = 3; k <= max_valence; ++k)
      r.corner.push_back(refine::doo_sabin_corner_weights(k));
    r.border_corner = {0.75, 0.25};
  } else if (name == "sqrt3") {
    // Sqrt3_mask_3: the fast host's weights (refine/primal_masks.h).
    r.host = "sqrt3";
    for_valences(refine::sqrt3_vertex_weights);
    const refine::Primal_mask m = refine::sqrt3_mask("sqrt3", {}).mask;
    r.border_edge = m.border_edge;
    r.border_vertex = m.border_vertex;
  } else if (name == "linear") {
    r.host = "pqq";
    for_valences([](double) { return Vertex_weights{1.0, 0.0, 0.0}; });
    r.edge_end = 0.5;
    r.edge_wing = 0.0;
    r.border_vertex = {0.0, 1.0, 0.0};
  }
  return r;
}

void custom_subdivision_step(Mesh& mesh, const Custom_rules& rules,
                             int level_index) {
  namespace SMI = CGAL::Subdivision_method_3::internal;
  auto vpm = get(CGAL::vertex_point, mesh);
  if (rules.host == "pqq") {
    SMI::PQQ_1step(mesh, vpm, Table_PQQ_mask_3<Mesh>(&mesh, vpm, &rules));
  } else if (rules.host == "ptq") {
    SMI::PTQ_1step(mesh, vpm, Table_PTQ_mask_3<Mesh>(&mesh, vpm, &rules));
  } else if (rules.host == "dqq") {
    // As cgal_driver.cpp's doo-sabin: CGAL's DQQ host on closed meshes, the
    // border-aware one of dqq_border_3.h on open ones.
    if (CGAL::is_closed(mesh))
      SMI::DQQ_1step(mesh, vpm, Table_DQQ_mask_3<Mesh>(&mesh, vpm, &rules));
    else
      internal::DQQ_border_1step(mesh,
                                 Table_DQQ_mask_3<Mesh>(&mesh, vpm, &rules));
  } else if (rules.host == "sqrt3") {
    // CGAL refines the border on every second step; level_index carries the
    // parity across calls, as cgal_driver.cpp does for sqrt3.
    SMI::Sqrt3_1step(mesh, vpm, Table_Sqrt3_mask_3<Mesh>(&mesh, vpm, &rules),
                     level_index % 2 == 1);
  }
}

}  // namespace subdivlab
