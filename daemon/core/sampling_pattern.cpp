#include "core/sampling_pattern.h"

#include <algorithm>
#include <cmath>

#include <glm/geometric.hpp>
#include <nanoflann.hpp>

#include "core/sphere_points.h"
#include "core/surface_parameterization.h"

namespace vem {
namespace {

// nanoflann's dataset adaptor over the first `count` points of dimension D.
template <class Vec>
struct PointCloud {
  const std::vector<Vec>* points = nullptr;
  std::size_t count = 0;

  [[nodiscard]] std::size_t kdtree_get_point_count() const { return count; }
  [[nodiscard]] double kdtree_get_pt(std::size_t i, std::size_t dim) const {
    return (*points)[i][int(dim)];
  }
  template <class Box>
  bool kdtree_get_bbox(Box& /*box*/) const {
    return false;
  }
};

template <class Vec>
using KdTree =
    nanoflann::KDTreeSingleIndexAdaptor<nanoflann::L2_Simple_Adaptor<double, PointCloud<Vec>>,
                                        PointCloud<Vec>, Vec::length(), std::size_t>;

// One Lloyd step for the points [first, last): each moves to the centroid of the density samples
// nearest to it among points [0, last). `project` maps a mean back onto the domain.
template <class Vec, class Project>
void lloydStep(std::vector<Vec>& points, std::size_t first, std::size_t last,
               const std::vector<Vec>& samples, Project project) {
  const PointCloud<Vec> cloud{&points, last};
  KdTree<Vec> tree(Vec::length(), cloud, nanoflann::KDTreeSingleIndexAdaptorParams(10));
  std::vector<Vec> sum(last - first, Vec(0));
  std::vector<std::size_t> hits(last - first, 0);
  for (const Vec& sample : samples) {
    std::size_t nearest = 0;
    double distanceSq = 0;
    tree.knnSearch(&sample[0], 1, &nearest, &distanceSq);
    if (nearest < first) continue;
    sum[nearest - first] += sample;
    ++hits[nearest - first];
  }
  for (std::size_t k = 0; k < sum.size(); ++k) {
    if (hits[k] > 0) points[first + k] = project(sum[k] / double(hits[k]), points[first + k]);
  }
}

// Runs the doubling levels; `samplesFor(last)` gives the density samples for a level.
template <class Vec, class Samples, class Project>
void relaxLevels(std::vector<Vec>& points, int iterations, Samples samplesFor, Project project) {
  const std::size_t count = points.size();
  for (std::size_t first = 0; first < count;) {
    const std::size_t last = std::min(count, first == 0 ? std::size_t(1) : 2 * first);
    const std::vector<Vec> samples = samplesFor(last);
    for (int step = 0; step < iterations; ++step) lloydStep(points, first, last, samples, project);
    first = last;
  }
}

std::vector<glm::dvec2> squareGrid(std::size_t count, int samplesPerPoint) {
  const int n = int(std::ceil(std::sqrt(double(samplesPerPoint) * double(count))));
  std::vector<glm::dvec2> grid;
  grid.reserve(std::size_t(n) * std::size_t(n));
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) grid.emplace_back((i + 0.5) / n, (j + 0.5) / n);
  return grid;
}

// Evenly spread samples on the layout's surface (Fibonacci lattice; its upper half for the
// hemisphere).
std::vector<glm::dvec3> surfaceSamples(MapLayout layout, std::size_t count, int samplesPerPoint) {
  const int wanted = int(std::size_t(samplesPerPoint) * count);
  if (layout == MapLayout::Sphere) return fibonacciSphere(wanted);
  std::vector<glm::dvec3> upper;
  for (const glm::dvec3& d : fibonacciSphere(2 * wanted)) {
    if (d.y > 0) upper.push_back(d);
  }
  return upper;
}

std::vector<glm::dvec2> relaxOnSurface(std::vector<glm::dvec2> square, const LloydOptions& o) {
  std::vector<glm::dvec3> dirs(square.size());
  for (std::size_t i = 0; i < square.size(); ++i)
    dirs[i] = surfaceDirection(o.layout, cylinderFromSquare(o.layout, square[i]));
  relaxLevels(
      dirs, o.iterations,
      [&](std::size_t last) { return surfaceSamples(o.layout, last, o.samplesPerPoint); },
      [](glm::dvec3 mean, glm::dvec3 old) {
        const double length = glm::length(mean);
        return length > 1e-12 ? mean / length : old;
      });
  for (std::size_t i = 0; i < square.size(); ++i)
    square[i] = squareFromCylinder(o.layout, cylinderFromSurfaceDirection(o.layout, dirs[i]));
  return square;
}

}  // namespace

double radicalInverse(std::uint32_t base, std::uint64_t index) {
  const double invBase = 1.0 / base;
  double factor = invBase;
  double result = 0;
  while (index > 0) {
    result += double(index % base) * factor;
    index /= base;
    factor *= invBase;
  }
  return result;
}

glm::dvec2 haltonPoint(std::uint64_t patternIndex) {
  return {radicalInverse(2, patternIndex + 1), radicalInverse(3, patternIndex + 1)};
}

std::vector<glm::dvec2> haltonPoints(std::size_t count) {
  std::vector<glm::dvec2> points(count);
  for (std::size_t i = 0; i < count; ++i) points[i] = haltonPoint(i);
  return points;
}

std::vector<glm::dvec2> relaxedHaltonPattern(std::size_t count, LloydOptions options) {
  std::vector<glm::dvec2> points = haltonPoints(count);
  if (options.domain == RelaxationDomain::Surface)
    return relaxOnSurface(std::move(points), options);
  relaxLevels(
      points, options.iterations,
      [&](std::size_t last) { return squareGrid(last, options.samplesPerPoint); },
      [](glm::dvec2 mean, glm::dvec2 /*old*/) { return mean; });
  return points;
}

}  // namespace vem
