// ProcessingOptions: what vemd's per-frame pipeline is asked to do (vemd/pipeline.h): the polar
// map's size, the light count and sampler, the temporal filter and the clustering. A plain value,
// shared by the pipeline, vemd's configuration and whatever changes it between frames
// (loop_control.h: the stream's control messages).
//
// Units: map sizes in pixels (columns over the azimuth, rows zenith to horizon); the cluster
// budget Q is about Q clusters over the hemisphere (paper section 4).
#pragma once

#include <cstddef>

#include "core/fir_design.h"
#include "core/light_clustering.h"
#include "core/light_generator.h"

namespace vem {

struct ProcessingOptions {
  int mapWidth = 1024;  // polar (hemisphere) map columns, over the azimuth
  int mapHeight = 256;  // rows, zenith to horizon
  std::size_t lightCount = 1024;
  SamplerKind sampler = SamplerKind::Havran;
  FilterPreset filter = FilterPreset::Paper9;
  bool clustering = true;
  int clusterBudget = 72;  // Q: about Q clusters over the hemisphere
  double clusterCorrectionFactor = kDefaultClusterCorrectionFactor;

  friend bool operator==(const ProcessingOptions&, const ProcessingOptions&) = default;
};

}  // namespace vem
