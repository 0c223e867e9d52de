// The layers of a differential composite (differential_composite.h), rendered by an ideal pinhole
// camera at the render size, resampled into the plate's pixels: the plate may be larger or smaller
// than the render, and its lens distorts (issue 21, "a plate whose size differs from the render
// size"). The plate is never resampled: what the camera saw stays pixel for pixel.
//
// renderPxOfPlatePx[i] is where plate pixel i's centre lands in the render, in render pixels
// (centres at +0.5, as the renderers'); the caller builds it once per plate camera and size (from
// the lens's undistortion). Empty: the plate is the render scaled, no lens distortion.
// Radiance is bilinear (edge pixels clamp; a position outside the render reads the nearest edge).
// Where an object's edge crosses a plate pixel (its four taps are neither all objects' nor all
// not), the objects' share of the taps' weight becomes objectCover and their radiance
// objectRadiance, and the layers and the class hold the other taps alone; elsewhere the class is
// the nearest render pixel's. So an object's edge does not step at a plate larger than the render,
// and the floor's shading does not bleed into the object's or back. An empty withoutObjects (no
// differential pass) stays empty.
#pragma once

#include <span>

#include <glm/vec2.hpp>

#include "client/render/differential_composite.h"

namespace vem::render {

[[nodiscard]] DifferentialLayers resampledLayers(const DifferentialLayers& rendered,
                                                 int plateWidthPx, int plateHeightPx,
                                                 std::span<const glm::vec2> renderPxOfPlatePx);

// Where plate pixel (x, y)'s centre lands in a widthPx x heightPx render of the same view, with no
// distortion: the same fraction of the image.
[[nodiscard]] glm::vec2 scaledRenderPx(int x, int y, int plateWidthPx, int plateHeightPx,
                                       int widthPx, int heightPx);

}  // namespace vem::render
