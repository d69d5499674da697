#include "dual_masks.h"

#include <CGAL/number_type_config.h>

#include <cmath>

namespace subdivlab {
namespace refine {

std::vector<double> doo_sabin_corner_weights(std::uint32_t k) {
  std::vector<double> w(k);
  const double n = k;
  for (std::uint32_t j = 0; j < k; ++j) {
    if (k == 4)
      w[j] = (j == 0 ? 9.0 : j == 2 ? 1.0 : 3.0) / 16.0;
    else
      w[j] = j == 0 ? (5.0 / n + 1) / 4
                    : (3 + 2 * std::cos(2 * j * CGAL_PI / n)) / n / 4;
  }
  return w;
}

Dual_mask_lookup dual_mask(const std::string& scheme,
                           const Custom_rules& custom) {
  Dual_mask_lookup r;
  r.ok = true;
  if (scheme == "doo-sabin") {
    r.mask.rule = doo_sabin_corner_weights;
  } else if (scheme == "custom" && custom.host == "dqq") {
    r.mask.first_degree = custom.first_degree;
    r.mask.corner = custom.corner;
    r.mask.border_corner = custom.border_corner;
  } else {
    r.ok = false;
  }
  return r;
}

}  // namespace refine
}  // namespace subdivlab
