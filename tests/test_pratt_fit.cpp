#include <doctest/doctest.h>

#include <random>

#include "core/pratt_fit.hpp"
#include "core/weight.hpp"

using namespace amls;

namespace {

template <int D>
PrattFit<D> fit_around(const Vec<D>& p, const std::vector<Vec<D>>& neighbours, double radius) {
  PrattFit<D> fit;
  for (const Vec<D>& q : neighbours) {
    const Vec<D> u = (q - p) / radius;
    fit.add(u, weight_of_squared_ratio(u.squaredNorm()));
  }
  return fit;
}

}  // namespace

TEST_CASE("Pratt fit reproduces a circle exactly: the pseudo-normal is radial") {
  const Vec<2> center(0.5, 0.75);
  const double r = 0.15;
  std::vector<Vec<2>> pts;
  for (int i = 0; i < 200; ++i) {
    const double a = 2.0 * M_PI * i / 200.0;
    pts.push_back(center + r * Vec<2>(std::cos(a), std::sin(a)));
  }
  for (int i : {0, 17, 99}) {
    auto fit = fit_around<2>(pts[i], pts, 0.03);
    Vec<2> n;
    const Vec<2> radial = (pts[i] - center) / r;
    REQUIRE(fit.solve(radial, n) == FitStatus::ok);
    CHECK((n - radial).norm() < 1e-9);
    // The fitted algebraic circle is the circle: its centre in scaled coordinates.
    const auto& a = fit.coefficients();
    const double a2 = a[3];
    const Vec<2> c = -a.segment<2>(1) / (2.0 * a2) * 0.03 + pts[i];
    CHECK((c - center).norm() < 1e-9);
  }
}

TEST_CASE("Pratt fit reproduces a sphere exactly") {
  const Vec<3> center(0.35, 0.35, 0.35);
  const double r = 0.15;
  std::vector<Vec<3>> pts;
  const int n = 4000;
  for (int i = 0; i < n; ++i) {
    const double z = 1.0 - (2.0 * i + 1.0) / n;
    const double s = std::sqrt(1 - z * z), phi = i * 2.399963229728653;
    pts.push_back(center + r * Vec<3>(s * std::cos(phi), s * std::sin(phi), z));
  }
  for (int i : {3, 1000, 2500}) {
    auto fit = fit_around<3>(pts[i], pts, 0.03);
    Vec<3> normal;
    const Vec<3> radial = (pts[i] - center) / r;
    REQUIRE(fit.solve(radial, normal) == FitStatus::ok);
    CHECK((normal - radial).norm() < 1e-9);
  }
}

TEST_CASE("Pratt fit orients the normal to agree with the carried one") {
  std::vector<Vec<2>> line;
  for (int i = -5; i <= 5; ++i) line.push_back(Vec<2>(0.01 * i, 0.0));
  auto fit = fit_around<2>(line[5], line, 0.06);
  Vec<2> n;
  REQUIRE(fit.solve(Vec<2>(0.2, -1.0).normalized(), n) == FitStatus::ok);
  CHECK(n.y() == doctest::Approx(-1.0).epsilon(1e-12));
  REQUIRE(fit.solve(Vec<2>(0.3, 1.0).normalized(), n) == FitStatus::ok);
  CHECK(n.y() == doctest::Approx(1.0).epsilon(1e-12));
}

TEST_CASE("Pratt fit recovers the normal of a noisy plane") {
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> u(-0.05, 0.05), noise(-1e-4, 1e-4);
  std::vector<Vec<3>> pts{Vec<3>::Zero()};
  for (int i = 0; i < 300; ++i) pts.push_back(Vec<3>(u(rng), u(rng), noise(rng)));
  auto fit = fit_around<3>(pts[0], pts, 0.05);
  Vec<3> n;
  REQUIRE(fit.solve(Vec<3>(0, 0, 1), n) == FitStatus::ok);
  CHECK(n.z() > 0.999);
}

TEST_CASE("Pratt fit reports degenerate neighbourhoods and keeps the carried normal") {
  const Vec<3> carried(0, 0, 1);
  SUBCASE("too few points") {
    auto fit = fit_around<3>(Vec<3>::Zero(), {Vec<3>::Zero(), Vec<3>(0.01, 0, 0), Vec<3>(0, 0.01, 0)}, 0.05);
    Vec<3> n = carried;
    CHECK(fit.solve(carried, n) == FitStatus::too_few_neighbours);
    CHECK(n == carried);
  }
  SUBCASE("collinear points in 3D") {
    std::vector<Vec<3>> pts;
    for (int i = -4; i <= 4; ++i) pts.push_back(Vec<3>(0.01 * i, 0.005 * i, 0.0));
    auto fit = fit_around<3>(pts[4], pts, 0.06);
    Vec<3> n = carried;
    CHECK(fit.solve(carried, n) == FitStatus::degenerate);
    CHECK(n == carried);
  }
  SUBCASE("coincident points in 2D") {
    auto fit = fit_around<2>(Vec<2>::Zero(), std::vector<Vec<2>>(5, Vec<2>::Zero()), 0.05);
    Vec<2> n(1, 0);
    CHECK(fit.solve(Vec<2>(1, 0), n) == FitStatus::degenerate);
  }
}
