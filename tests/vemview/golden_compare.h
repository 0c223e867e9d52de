// Golden pictures of vemview's suites: an 8-bit sRGB picture against tests/vemview/golden/NAME.
// Tolerance: the mean absolute difference of the 8-bit values below kGoldenMeanTolerance and at
// most kGoldenOutlierFraction of the values off by more than kGoldenOutlierLevels (rasteriser and
// driver differences move a few silhouette and shadow-edge pixels). A failing picture is saved as
// $TMPDIR/failed-NAME. Update mode: VEM_UPDATE_GOLDEN=1 rewrites the golden pictures from this
// build (then review them and commit), and the tests report that they updated rather than
// compared.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

namespace vem::testing {

inline constexpr double kGoldenMeanTolerance = 1.5;
inline constexpr double kGoldenOutlierFraction = 0.01;
inline constexpr int kGoldenOutlierLevels = 24;

// srgb8: widthPx * heightPx * 3 bytes, RGB, row 0 at the top. Fails the running test.
void compareSrgb8WithGolden(const std::vector<std::uint8_t>& srgb8, int widthPx, int heightPx,
                            const std::string& name);

}  // namespace vem::testing
