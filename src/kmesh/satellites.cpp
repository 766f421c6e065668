#include "kmesh/satellites.hpp"

#include "exact/error.hpp"

namespace kmr::kmesh {
namespace {

// First quadrant, rays 0..6: 0°, ≈15°, ≈30°, ≈45°, ≈60°, ≈75°, 90°. The triples come from
// (m² − n², 2mn, m² + n²) with n/m ≈ tan(kπ/24): 5/38 (14.992°), 15/56 (29.990°), 12/29 (44.959°);
// rays 4 and 5 swap the coordinates of rays 2 and 1.
constexpr RayVector kQuadrant[7] = {{1, 0, 1},          {1419, 380, 1469}, {2911, 1680, 3361},
                                    {697, 696, 985},    {1680, 2911, 3361}, {380, 1419, 1469},
                                    {0, 1, 1}};

}  // namespace

RayVector ray_vector(int k) {
  KMR_CHECK(k >= 0 && k < kRays, "ray index out of range");
  RayVector r = kQuadrant[k % 6];
  for (int q = 0; q < k / 6; ++q) r = {-r.b, r.a, r.c};  // rotate by 90°
  return r;
}

Point2 satellite_offset(int ray, std::int64_t rank) {
  RayVector r = ray_vector(ray);
  KMR_CHECK(kScale % r.c == 0, "kScale is not a multiple of a hypotenuse");
  std::int64_t f = kScale / r.c;
  return {Dyadic(exact::Integer(r.a) * f, rank), Dyadic(exact::Integer(r.b) * f, rank)};
}

Point2 satellite_position(const Point2& nucleus, int ray, std::int64_t rank) {
  Point2 o = satellite_offset(ray, rank);
  return {nucleus[0] + o[0], nucleus[1] + o[1]};
}

std::array<int, 12> rays_of_rank(std::int64_t rank) {
  std::array<int, 12> out{};
  int first = static_cast<int>(((rank % 2) + 2) % 2);
  for (int i = 0; i < 12; ++i) out[i] = first + 2 * i;
  return out;
}

}  // namespace kmr::kmesh
