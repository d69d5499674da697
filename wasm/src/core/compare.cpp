#include "compare.h"

#include <CGAL/Orthogonal_k_neighbor_search.h>
#include <CGAL/Search_traits_3.h>
#include <CGAL/Search_traits_adapter.h>
#include <CGAL/Simple_cartesian.h>
#include <CGAL/property_map.h>

#include <algorithm>
#include <cmath>
#include <set>
#include <tuple>
#include <vector>

#include "mesh_facts.h"

namespace subdivlab {
namespace {

using K = CGAL::Simple_cartesian<double>;
using Point = K::Point_3;
using Point_and_index = std::tuple<Point, std::uint32_t>;
using Traits = CGAL::Search_traits_adapter<
    Point_and_index, CGAL::Nth_of_tuple_property_map<0, Point_and_index>,
    CGAL::Search_traits_3<K>>;
using Search = CGAL::Orthogonal_k_neighbor_search<Traits>;

Point point_of(const Mesh_buffers& m, std::uint32_t v) {
  return {m.positions[3 * v], m.positions[3 * v + 1], m.positions[3 * v + 2]};
}

double distance(const Mesh_buffers& a, std::uint32_t u, const Mesh_buffers& b,
                std::uint32_t v) {
  return std::sqrt(CGAL::squared_distance(point_of(a, u), point_of(b, v)));
}

/// Each face as the cycle of its vertices through `map` (identity when
/// empty), starting at the smallest, so that the same faces compare equal
/// whatever corner a mesh lists first.
std::multiset<std::vector<std::uint32_t>> face_cycles(
    const Mesh_buffers& m, const std::vector<std::uint32_t>& map) {
  std::multiset<std::vector<std::uint32_t>> out;
  std::size_t o = 0;
  for (std::uint32_t size : m.face_sizes) {
    std::vector<std::uint32_t> face;
    for (std::uint32_t j = 0; j < size; ++j) {
      const std::uint32_t v = m.face_indices[o + j];
      face.push_back(map.empty() ? v : map[v]);
    }
    o += size;
    std::rotate(face.begin(), std::min_element(face.begin(), face.end()),
                face.end());
    out.insert(std::move(face));
  }
  return out;
}

std::string count_text(std::uint64_t n, const std::string& what) {
  if (n == 1) return "1 " + what;
  return std::to_string(n) + " " + (what == "vertex" ? "vertices" : what + "s");
}

}  // namespace

Mesh_comparison compare_meshes(const Mesh_buffers& reference,
                               const Mesh_buffers& candidate,
                               double relative_tolerance, std::size_t worst) {
  Mesh_comparison c;
  const auto R = static_cast<std::uint32_t>(reference.vertex_count());
  const auto C = static_cast<std::uint32_t>(candidate.vertex_count());
  c.vertices[0] = R;
  c.vertices[1] = C;
  c.faces[0] = reference.face_count();
  c.faces[1] = candidate.face_count();
  c.diagonal = bbox_diagonal({&reference});
  c.tolerance = relative_tolerance * c.diagonal;
  if (R != C)
    c.reasons.push_back("the result has " + count_text(C, "vertex") +
                        " where the reference has " + std::to_string(R));
  if (c.faces[0] != c.faces[1])
    c.reasons.push_back("the result has " + count_text(c.faces[1], "face") +
                        " where the reference has " +
                        std::to_string(c.faces[0]));

  // The matching: in order when the counts agree and every vertex is
  // within the tolerance that way, else the nearest reference vertex.
  std::vector<std::uint32_t> map(C);
  std::vector<double> error(C, 0.0);
  bool in_order = R == C;
  for (std::uint32_t v = 0; in_order && v < C; ++v) {
    map[v] = v;
    error[v] = distance(candidate, v, reference, v);
    in_order = error[v] <= c.tolerance;
  }
  c.matching = in_order ? "order" : "nearest";
  if (!in_order && R > 0) {
    std::vector<Point_and_index> points;
    points.reserve(R);
    for (std::uint32_t v = 0; v < R; ++v)
      points.emplace_back(point_of(reference, v), v);
    Search::Tree tree(points.begin(), points.end());
    for (std::uint32_t v = 0; v < C; ++v) {
      const Search search(tree, point_of(candidate, v), 1);
      const auto nearest = search.begin();
      map[v] = std::get<1>(nearest->first);
      error[v] = std::sqrt(nearest->second);
    }
  }

  // One-to-one, and the same faces through it.
  std::vector<std::uint8_t> taken(R, 0);
  bool bijective = R == C;
  for (std::uint32_t v = 0; bijective && v < C; ++v) {
    bijective = taken[map[v]] == 0;
    taken[map[v]] = 1;
  }
  if (R == C && !bijective)
    c.reasons.push_back(
        "two vertices of the result are nearest to one vertex of the "
        "reference, so no one-to-one matching was found");
  if (bijective && c.faces[0] == c.faces[1]) {
    c.same_faces = face_cycles(candidate, map) == face_cycles(reference, {});
    if (!c.same_faces)
      c.reasons.push_back(
          "the faces differ: through the vertex matching, some face of the "
          "result is not a face of the reference (or turns the other way)");
  }

  double sum = 0;
  std::size_t far = 0;
  for (std::uint32_t v = 0; v < C; ++v) {
    sum += error[v];
    c.max_error = std::max(c.max_error, error[v]);
    if (error[v] > c.tolerance) ++far;
  }
  c.mean_error = C > 0 ? sum / C : 0;
  if (far > 0)
    c.reasons.push_back(count_text(far, "vertex") + " of " + std::to_string(C) +
                        (far == 1 ? " is" : " are") +
                        " farther from the reference than the tolerance");
  std::vector<std::uint32_t> order(C);
  for (std::uint32_t v = 0; v < C; ++v) order[v] = v;
  const std::size_t n = std::min<std::size_t>(worst, C);
  std::partial_sort(order.begin(), order.begin() + n, order.end(),
                    [&](std::uint32_t a, std::uint32_t b) {
                      return error[a] > error[b] ||
                             (error[a] == error[b] && a < b);
                    });
  for (std::size_t i = 0; i < n; ++i)
    c.worst.push_back({order[i], map[order[i]], error[order[i]]});
  c.match = c.reasons.empty();
  c.matched = std::move(map);
  c.errors = std::move(error);
  return c;
}

}  // namespace subdivlab
