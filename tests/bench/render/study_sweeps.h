// The sweeps of the render study (issue 7, "What accuracy costs in time"): which renderer draws the
// study scene with which lighting options. Each sweep varies one parameter around the base point
// N = 256 lights, S = min(N, 64) shadow maps of 256 px, angular regions on, no clustering:
//   a  N = 4 ... 1024 (S = min(N, 64)), OpenGL and Embree;
//   b  S = 0, 4, 16, 64, 256 at N = 256, OpenGL;
//   c  shadow-map resolution 64 ... 1024 px at N = 256, S = 64, OpenGL;
//   d  regions on and off at N = 16 ... 1024, OpenGL and Embree;
//   e  clustering Q = 8, 32, 128 and off at N = 256 and 1024, OpenGL and Embree;
//   f  N = 64 ... 1024 at S = 64, the maps shared by group or the nearest caster's, OpenGL.
// Embree traces a shadow ray for every light, so S and the resolution do not change its image.
#pragma once

#include <string>
#include <vector>

#include "client/render/shading_lights.h"

namespace vem::bench {

enum class RendererKind { Gl, Embree };
[[nodiscard]] const char* rendererLabel(RendererKind kind);  // "OpenGL", "Embree"

struct StudyConfig {
  RendererKind renderer = RendererKind::Gl;
  render::LightingOptions lighting;  // glossyPass and clusterLayout are set per scene and map
  int shadowMapPx = 256;

  // Equal for configurations that render the same image the same way (the measurement cache).
  [[nodiscard]] std::string key() const;
};

struct SweepPoint {
  StudyConfig config;
  std::string label;  // the varied parameter's value, e.g. "64"
};

struct SweepSeries {
  std::string name;  // e.g. "OpenGL, regions off"
  std::vector<SweepPoint> points;
};

struct Sweep {
  std::string id;        // "a"
  std::string title;     // "Light count N"
  std::string variable;  // the column heading of the varied parameter, e.g. "N"
  std::vector<SweepSeries> series;
};

// With withGl false, the OpenGL series are left out (no GL context on this machine).
[[nodiscard]] std::vector<Sweep> studySweeps(bool withGl);

}  // namespace vem::bench
