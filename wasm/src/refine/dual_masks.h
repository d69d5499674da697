// The mask of the DQQ host (dual_hosts.h) as weights: Doo-Sabin's corner
// rule and the border rule of dqq_border_3.h, in the form of custom rules
// (custom_rules.h) so that built-in and custom schemes run through one
// kernel. Doo-Sabin's weights are defined here once; the custom-rule preset
// "doo-sabin" reads them from here.
//
// Rules (p_0 the corner's vertex, p_j the vertex j steps after it around
// the face of degree k):
//   corner point     sum_j corner(k)[j] p_j
//   border corner    a corner on a border edge (p_0, q): border_corner[0]
//                    p_0 + border_corner[1] q (Chaikin's 3/4, 1/4)
#pragma once

#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include "core/custom_rules.h"

namespace subdivlab {
namespace refine {

/// DooSabin_mask_3 at degree k: 9/16, 3/16, 1/16, 3/16 for quads, else
/// (5/k + 1)/4 at the corner and (3 + 2 cos(2 pi j / k)) / (4k) at p_j.
std::vector<double> doo_sabin_corner_weights(std::uint32_t k);

struct Dual_mask {
  /// Corner weights at degree k: rule(k) when set, else the table
  /// corner[k - first_degree].
  std::vector<double> (*rule)(std::uint32_t k) = nullptr;
  int first_degree = 3;
  std::vector<std::vector<double>> corner;
  std::array<double, 2> border_corner{0.75, 0.25};

  /// Whether degree k has weights.
  bool covers(std::uint32_t k) const {
    return rule != nullptr || (k >= static_cast<std::uint32_t>(first_degree) &&
                               k - first_degree < corner.size());
  }
  /// Precondition: covers(k).
  std::vector<double> corner_weights(std::uint32_t k) const {
    return rule != nullptr ? rule(k) : corner[k - first_degree];
  }
};

/// The mask of a scheme with the dual fast host: doo-sabin, or custom with
/// the dqq host (`custom` then gives the weights). `ok` false for any other.
struct Dual_mask_lookup {
  bool ok = false;
  Dual_mask mask;
};
Dual_mask_lookup dual_mask(const std::string& scheme,
                           const Custom_rules& custom);

}  // namespace refine
}  // namespace subdivlab
