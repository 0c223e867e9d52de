#include "core/cube_map_lookup.h"

#include <algorithm>
#include <cmath>
#include <glm/geometric.hpp>

#include "util/contract.h"

namespace vem {
namespace {

// The (sc, tc, ma) of the OpenGL table for a direction already known to lie on `face`.
struct FaceAxes {
  double sc;
  double tc;
  double ma;
};

FaceAxes faceAxes(CubeFace face, glm::dvec3 d) {
  switch (face) {
    case CubeFace::PosX: return {-d.z, -d.y, d.x};
    case CubeFace::NegX: return {d.z, -d.y, -d.x};
    case CubeFace::PosY: return {d.x, d.z, d.y};
    case CubeFace::NegY: return {d.x, -d.z, -d.y};
    case CubeFace::PosZ: return {d.x, -d.y, d.z};
    case CubeFace::NegZ: return {-d.x, -d.y, -d.z};
  }
  return {0.0, 0.0, 1.0};
}

CubeFace majorFace(glm::dvec3 d) {
  const glm::dvec3 a = glm::abs(d);
  if (a.x >= a.y && a.x >= a.z) return d.x >= 0.0 ? CubeFace::PosX : CubeFace::NegX;
  if (a.y >= a.z) return d.y >= 0.0 ? CubeFace::PosY : CubeFace::NegY;
  return d.z >= 0.0 ? CubeFace::PosZ : CubeFace::NegZ;
}

int texelCoord(double unit, int faceSize) {
  return std::clamp(int(std::floor(unit * faceSize)), 0, faceSize - 1);
}

}  // namespace

CubeFaceCoord cubeFaceCoordOf(glm::dvec3 dir) {
  VEM_EXPECTS(dir.x != 0.0 || dir.y != 0.0 || dir.z != 0.0);
  const CubeFace face = majorFace(dir);
  const FaceAxes axes = faceAxes(face, dir);
  return {face, 0.5 * (axes.sc / axes.ma + 1.0), 0.5 * (axes.tc / axes.ma + 1.0)};
}

glm::dvec3 directionFromCubeFaceCoord(const CubeFaceCoord& coord) {
  const double sc = 2.0 * coord.s - 1.0;
  const double tc = 2.0 * coord.t - 1.0;
  glm::dvec3 d{0.0};
  switch (coord.face) {
    case CubeFace::PosX: d = {1.0, -tc, -sc}; break;
    case CubeFace::NegX: d = {-1.0, -tc, sc}; break;
    case CubeFace::PosY: d = {sc, 1.0, tc}; break;
    case CubeFace::NegY: d = {sc, -1.0, -tc}; break;
    case CubeFace::PosZ: d = {sc, -tc, 1.0}; break;
    case CubeFace::NegZ: d = {-sc, -tc, -1.0}; break;
  }
  return glm::normalize(d);
}

CubeTexel cubeTexelOf(glm::dvec3 dir, int faceSize) {
  const CubeFaceCoord coord = cubeFaceCoordOf(dir);
  return {coord.face, texelCoord(coord.s, faceSize), texelCoord(coord.t, faceSize)};
}

glm::dvec3 cubeTexelCentreDirection(const CubeTexel& texel, int faceSize) {
  const double size = faceSize;
  return directionFromCubeFaceCoord(
      {texel.face, (texel.column + 0.5) / size, (texel.row + 0.5) / size});
}

double cubeTexelRadiusRad(const CubeTexel& texel, int faceSize) {
  const glm::dvec3 centre = cubeTexelCentreDirection(texel, faceSize);
  const double size = faceSize;
  double largest = 0.0;
  for (int corner = 0; corner < 4; ++corner) {
    const double s = (texel.column + (corner & 1)) / size;
    const double t = (texel.row + (corner >> 1)) / size;
    const glm::dvec3 d = directionFromCubeFaceCoord({texel.face, s, t});
    largest = std::max(largest, std::acos(std::clamp(glm::dot(centre, d), -1.0, 1.0)));
  }
  return largest;
}

std::size_t cubeTexelCount(int faceSize) {
  return std::size_t(kCubeFaceCount) * std::size_t(faceSize) * std::size_t(faceSize);
}

std::size_t cubeTexelIndex(const CubeTexel& texel, int faceSize) {
  const std::size_t size = std::size_t(faceSize);
  return (std::size_t(texel.face) * size + std::size_t(texel.row)) * size +
         std::size_t(texel.column);
}

CubeTexel cubeTexelFromIndex(std::size_t index, int faceSize) {
  VEM_EXPECTS(index < cubeTexelCount(faceSize));
  const std::size_t size = std::size_t(faceSize);
  return {CubeFace(index / (size * size)), int(index % size), int((index / size) % size)};
}

}  // namespace vem
