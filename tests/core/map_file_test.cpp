// Tests of vem_mapio's loadMap/saveMap. Orientation and channel order are checked against files
// written byte by byte from the format specifications (OpenEXR, PFM, Radiance RGBE), so a flip or a
// BGR/RGB swap that the writer and the reader share still fails; round trips then check the
// writers.
#include "mapio/map_file.h"

#include <gtest/gtest.h>
#include <sys/resource.h>
#include <unistd.h>

#include <algorithm>
#include <bit>
#include <cmath>
#include <csignal>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <limits>
#include <map>
#include <random>
#include <string>

namespace vem::mapio {
namespace {

namespace fs = std::filesystem;

// A fresh folder under the system's temporary folder, removed with everything in it.
class TempDir {
 public:
  TempDir()
      : path_(fs::temp_directory_path() / ("vem-map-file-test-" + std::to_string(::getpid()) + "-" +
                                           std::to_string(std::random_device{}()))) {
    fs::create_directories(path_);
  }
  TempDir(const TempDir&) = delete;
  TempDir& operator=(const TempDir&) = delete;
  ~TempDir() {
    std::error_code ignored;
    fs::remove_all(path_, ignored);
  }
  [[nodiscard]] fs::path operator/(const std::string& name) const { return path_ / name; }
  [[nodiscard]] const fs::path& path() const { return path_; }

 private:
  fs::path path_;
};

void writeFile(const fs::path& path, const std::string& bytes) {
  std::ofstream(path, std::ios::binary) << bytes;
}

std::string readFile(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), {}};
}

// Distinct values per pixel: R grows with x, G with y, and R > B everywhere, all exact in float.
EnvMap patternMap(int width, int height) {
  EnvMap map = EnvMap::filled(MapLayout::Sphere, width, height, glm::vec3(0));
  for (int y = 0; y < height; ++y)
    for (int x = 0; x < width; ++x)
      map.set(x, y,
              {4.0f + float(x) + 0.25f * float(y), 2.0f + 0.5f * float(y),
               1.0f + 0.125f * float(x + y)});
  return map;
}

// Every channel within `relative` of the pixel's largest expected channel (RGBE shares an
// exponent).
void expectSamePixels(const EnvMap& got, const EnvMap& want, float relative = 0.0f) {
  ASSERT_EQ(got.width, want.width);
  ASSERT_EQ(got.height, want.height);
  for (int y = 0; y < want.height; ++y)
    for (int x = 0; x < want.width; ++x) {
      const glm::vec3 g = got.at(x, y), w = want.at(x, y);
      const float tolerance = relative * std::max({w.r, w.g, w.b});
      for (int c = 0; c < 3; ++c)
        ASSERT_NEAR(g[c], w[c], tolerance) << "pixel (" << x << ", " << y << ") channel " << c;
    }
}

template <typename T>
void put(std::string& out, T value) {
  out.append(reinterpret_cast<const char*>(&value), sizeof value);  // little-endian host
}

struct Window {
  std::int32_t xMin, yMin, xMax, yMax;
};

// An uncompressed scanline OpenEXR file of FLOAT channels, each holding its values over the data
// window row by row (OpenEXR file layout, openexr.com "OpenEXR File Layout").
std::string handWrittenExr(const std::map<std::string, std::vector<float>>& channels, Window data,
                           Window display) {
  std::string out("\x76\x2f\x31\x01", 4);
  put(out, std::int32_t{2});
  const auto attribute = [&](const std::string& name, const std::string& type,
                             const std::string& value) {
    out += name + '\0' + type + '\0';
    put(out, std::int32_t(value.size()));
    out += value;
  };
  const auto box = [](Window w) {
    std::string s;
    for (std::int32_t v : {w.xMin, w.yMin, w.xMax, w.yMax}) put(s, v);
    return s;
  };
  const auto bytesOf = [](auto value) {
    std::string s;
    put(s, value);
    return s;
  };
  std::string list;
  for (const auto& [name, values] : channels) {
    list += name + '\0';
    for (std::int32_t v : {2, 0, 1, 1})
      put(list, v);  // FLOAT, pLinear + reserved, x and y sampling
  }
  attribute("channels", "chlist", list + '\0');
  attribute("compression", "compression", std::string(1, '\0'));
  attribute("dataWindow", "box2i", box(data));
  attribute("displayWindow", "box2i", box(display));
  attribute("lineOrder", "lineOrder", std::string(1, '\0'));
  attribute("pixelAspectRatio", "float", bytesOf(1.0f));
  attribute("screenWindowCenter", "v2f", bytesOf(0.0f) + bytesOf(0.0f));
  attribute("screenWindowWidth", "float", bytesOf(1.0f));
  out += '\0';
  const int width = data.xMax - data.xMin + 1, height = data.yMax - data.yMin + 1;
  const std::size_t table = out.size();
  out.append(8 * std::size_t(height), '\0');
  for (int row = 0; row < height; ++row) {
    const std::uint64_t offset = out.size();
    std::memcpy(out.data() + table + 8 * std::size_t(row), &offset, 8);
    put(out, std::int32_t(data.yMin + row));
    put(out, std::int32_t(channels.size() * std::size_t(width) * 4));
    for (const auto& [name, values] : channels)
      for (int x = 0; x < width; ++x) put(out, values.at(std::size_t(row * width + x)));
  }
  return out;
}

// Channel `c` of patternMap(width, height) as one EXR channel, row by row.
std::vector<float> patternChannel(int width, int height, int c) {
  const EnvMap map = patternMap(width, height);
  std::vector<float> values;
  for (std::size_t i = 0; i < map.pixelCount(); ++i)
    values.push_back(map.rgb[3 * i + std::size_t(c)]);
  return values;
}

TEST(MapFileExr, ChannelsLoadByNameWithRowZeroAtTheTopOfTheFile) {
  const TempDir dir;
  const Window window{0, 0, 7, 3};
  writeFile(dir / "pattern.exr", handWrittenExr({{"B", patternChannel(8, 4, 2)},
                                                 {"G", patternChannel(8, 4, 1)},
                                                 {"R", patternChannel(8, 4, 0)}},
                                                window, window));
  const auto map = loadMap(dir / "pattern.exr");
  ASSERT_TRUE(map) << map.error().message;
  EXPECT_EQ(map->layout, MapLayout::Sphere);
  expectSamePixels(*map, patternMap(8, 4));
}

TEST(MapFileExr, DataWindowAwayFromTheOriginLoadsWhole) {
  const TempDir dir;
  const Window window{-3, 7, 4, 10};
  writeFile(dir / "offset.exr", handWrittenExr({{"B", patternChannel(8, 4, 2)},
                                                {"G", patternChannel(8, 4, 1)},
                                                {"R", patternChannel(8, 4, 0)}},
                                               window, window));
  const auto map = loadMap(dir / "offset.exr");
  ASSERT_TRUE(map) << map.error().message;
  expectSamePixels(*map, patternMap(8, 4));
}

TEST(MapFileExr, DataWindowInsideTheDisplayWindowIsPlacedThereAndPaddedWithZeros) {
  const TempDir dir;
  writeFile(dir / "inset.exr", handWrittenExr({{"B", patternChannel(4, 2, 2)},
                                               {"G", patternChannel(4, 2, 1)},
                                               {"R", patternChannel(4, 2, 0)}},
                                              {2, 1, 5, 2}, {0, 0, 7, 3}));
  const auto map = loadMap(dir / "inset.exr");
  ASSERT_TRUE(map) << map.error().message;
  ASSERT_EQ(map->width, 8);
  ASSERT_EQ(map->height, 4);
  const EnvMap inset = patternMap(4, 2);
  for (int y = 0; y < 4; ++y)
    for (int x = 0; x < 8; ++x) {
      const bool inside = x >= 2 && x <= 5 && y >= 1 && y <= 2;
      const glm::vec3 want = inside ? inset.at(x - 2, y - 1) : glm::vec3(0);
      EXPECT_EQ(map->at(x, y), want) << "pixel (" << x << ", " << y << ")";
    }
}

TEST(MapFileExr, LuminanceOnlyFileLoadsGrey) {
  const TempDir dir;
  const Window window{0, 0, 7, 3};
  writeFile(dir / "grey.exr", handWrittenExr({{"Y", patternChannel(8, 4, 0)}}, window, window));
  const auto map = loadMap(dir / "grey.exr");
  ASSERT_TRUE(map) << map.error().message;
  const EnvMap pattern = patternMap(8, 4);
  for (int y = 0; y < 4; ++y)
    for (int x = 0; x < 8; ++x) EXPECT_EQ(map->at(x, y), glm::vec3(pattern.at(x, y).r));
}

TEST(MapFileExr, FileWithoutColourOrLuminanceChannelsIsBadContents) {
  const TempDir dir;
  const Window window{0, 0, 7, 3};
  writeFile(dir / "alpha.exr", handWrittenExr({{"A", patternChannel(8, 4, 0)}}, window, window));
  const auto map = loadMap(dir / "alpha.exr");
  ASSERT_FALSE(map);
  EXPECT_EQ(map.error().cause, MapFileError::BadContents);
  EXPECT_NE(map.error().message.find("R, G and B"), std::string::npos) << map.error().message;
}

TEST(MapFileExr, AbsurdDisplayWindowIsRefusedBeforeReadingPixels) {
  const TempDir dir;
  writeFile(dir / "huge.exr", handWrittenExr({{"Y", {1.0f}}}, {0, 0, 0, 0}, {0, 0, 99999, 49999}));
  const auto map = loadMap(dir / "huge.exr");
  ASSERT_FALSE(map);
  EXPECT_EQ(map.error().cause, MapFileError::BadContents);
  EXPECT_NE(map.error().message.find("100000 x 50000"), std::string::npos) << map.error().message;
}

TEST(MapFilePfm, BottomUpRowsLoadWithRowZeroAtTheTopAndRedFirst) {
  const TempDir dir;
  std::string pfm = "PF\n4 2\n-1.0\n";  // negative scale: little-endian; rows stored bottom to top
  const EnvMap pattern = patternMap(4, 2);
  for (int y : {1, 0})
    for (int x = 0; x < 4; ++x)
      for (int c = 0; c < 3; ++c) put(pfm, pattern.at(x, y)[c]);
  writeFile(dir / "pattern.pfm", pfm);
  const auto map = loadMap(dir / "pattern.pfm");
  ASSERT_TRUE(map) << map.error().message;
  expectSamePixels(*map, pattern);
}

TEST(MapFilePfm, GreyPfLoadsGrey) {
  const TempDir dir;
  std::string pfm = "Pf\n4 2\n-1.0\n";
  for (float v : {5.0f, 6.0f, 7.0f, 8.0f, 1.0f, 2.0f, 3.0f, 4.0f}) put(pfm, v);
  writeFile(dir / "grey.pfm", pfm);
  const auto map = loadMap(dir / "grey.pfm");
  ASSERT_TRUE(map) << map.error().message;
  EXPECT_EQ(map->at(0, 0), glm::vec3(1.0f));
  EXPECT_EQ(map->at(3, 1), glm::vec3(8.0f));
}

TEST(MapFileHdr, RgbeBytesLoadWithRowZeroAtTheTopAndRedFirst) {
  const TempDir dir;
  std::string hdr = "#?RADIANCE\nFORMAT=32-bit_rle_rgbe\n\n-Y 2 +X 4\n";  // flat: width < 8
  for (int y = 0; y < 2; ++y)
    for (int x = 0; x < 4; ++x)  // value = mantissa * 2^(exponent - 136) = mantissa / 128
      hdr += {char(128 + x + 8 * y), char(32 + 8 * y), char(64), char(129)};
  writeFile(dir / "rgbe.hdr", hdr);
  const auto map = loadMap(dir / "rgbe.hdr");
  ASSERT_TRUE(map) << map.error().message;
  for (int y = 0; y < 2; ++y)
    for (int x = 0; x < 4; ++x)
      EXPECT_EQ(map->at(x, y), glm::vec3(float(128 + x + 8 * y), float(32 + 8 * y), 64.0f) / 128.0f)
          << "pixel (" << x << ", " << y << ")";
}

TEST(MapFileRoundTrip, EachFormatKeepsPixelsRowsAndChannels) {
  const TempDir dir;
  const EnvMap pattern = patternMap(16, 8);
  for (const auto& [name, relative] :
       {std::pair{"map.exr", 0.0f}, {"map.pfm", 0.0f}, {"map.hdr", 0.01f}, {"MAP.EXR", 0.0f}}) {
    SCOPED_TRACE(name);
    const auto saved = saveMap(pattern, dir / name);
    ASSERT_TRUE(saved) << saved.error().message;
    const auto map = loadMap(dir / name);
    ASSERT_TRUE(map) << map.error().message;
    EXPECT_EQ(map->layout, MapLayout::Sphere);
    expectSamePixels(*map, pattern, relative);
  }
}

TEST(MapFileRoundTrip, NanInfAndNegativeValuesSurviveUntouched) {
  const TempDir dir;
  EnvMap map = patternMap(4, 2);
  const float specials[] = {std::numeric_limits<float>::quiet_NaN(),
                            std::numeric_limits<float>::infinity(),
                            -std::numeric_limits<float>::infinity(),
                            -2.5f,
                            -0.0f,
                            std::numeric_limits<float>::denorm_min()};
  for (std::size_t i = 0; i < std::size(specials); ++i) map.rgb[4 * i] = specials[i];
  for (const char* name : {"special.pfm", "special.exr"}) {
    SCOPED_TRACE(name);
    ASSERT_TRUE(saveMap(map, dir / name));
    const auto loaded = loadMap(dir / name);
    ASSERT_TRUE(loaded) << loaded.error().message;
    ASSERT_EQ(loaded->rgb.size(), map.rgb.size());
    for (std::size_t i = 0; i < map.rgb.size(); ++i)
      EXPECT_EQ(std::bit_cast<std::uint32_t>(loaded->rgb[i]),
                std::bit_cast<std::uint32_t>(map.rgb[i]))
          << "float " << i;
  }
}

TEST(MapFileLayout, DefaultFollowsTheAspectRatioAndAnExplicitLayoutWins) {
  EXPECT_EQ(defaultLayout(512, 256), MapLayout::Sphere);
  EXPECT_EQ(defaultLayout(360, 90), MapLayout::Hemisphere);
  EXPECT_EQ(defaultLayout(300, 100), std::nullopt);
  EXPECT_EQ(defaultLayout(0, 0), std::nullopt);

  const TempDir dir;
  ASSERT_TRUE(saveMap(patternMap(8, 2), dir / "polar.pfm"));
  ASSERT_TRUE(saveMap(patternMap(6, 2), dir / "odd.pfm"));
  EXPECT_EQ(loadMap(dir / "polar.pfm")->layout, MapLayout::Hemisphere);
  EXPECT_EQ(loadMap(dir / "polar.pfm", MapLayout::Sphere)->layout, MapLayout::Sphere);
  const auto odd = loadMap(dir / "odd.pfm");
  ASSERT_FALSE(odd);
  EXPECT_EQ(odd.error().cause, MapFileError::BadContents);
  EXPECT_NE(odd.error().message.find("6 x 2"), std::string::npos) << odd.error().message;
  EXPECT_EQ(loadMap(dir / "odd.pfm", MapLayout::Hemisphere)->layout, MapLayout::Hemisphere);
}

TEST(MapFileSharedHdri, EveryShippedExrLoadsAsA512By256FiniteSphere) {
  const fs::path folder = fs::path(VEM_SHARED_DATA_DIR) / "hdri";
  if (!fs::is_directory(folder)) GTEST_SKIP() << folder << " is absent";
  int files = 0;
  for (const fs::directory_entry& entry : fs::directory_iterator(folder)) {
    if (entry.path().extension() != ".exr") continue;
    SCOPED_TRACE(entry.path().string());
    ++files;
    const auto map = loadMap(entry.path());
    ASSERT_TRUE(map) << map.error().message;
    EXPECT_EQ(map->width, 512);
    EXPECT_EQ(map->height, 256);
    EXPECT_EQ(map->layout, MapLayout::Sphere);
    EXPECT_TRUE(std::ranges::all_of(map->rgb, [](float v) { return std::isfinite(v); }));
    EXPECT_TRUE(std::ranges::any_of(map->rgb, [](float v) { return v > 0; }));
  }
  EXPECT_GT(files, 0);
}

TEST(MapFileErrors, MissingFileIsNotFoundAndNamesThePath) {
  const TempDir dir;
  const auto map = loadMap(dir / "absent.exr");
  ASSERT_FALSE(map);
  EXPECT_EQ(map.error().cause, MapFileError::NotFound);
  EXPECT_NE(map.error().message.find((dir / "absent.exr").string()), std::string::npos);
}

TEST(MapFileErrors, FolderAndEmptyFileAreErrors) {
  const TempDir dir;
  fs::create_directory(dir / "folder.exr");
  writeFile(dir / "empty.pfm", "");
  EXPECT_EQ(loadMap(dir / "folder.exr").error().cause, MapFileError::Unreadable);
  EXPECT_EQ(loadMap(dir / "empty.pfm").error().cause, MapFileError::BadContents);
}

TEST(MapFileErrors, UnknownExtensionIsUnsupportedFormatAndListsTheFormats) {
  const TempDir dir;
  writeFile(dir / "map.png", "not read");
  for (const char* name : {"map.png", "map"}) {
    const auto map = loadMap(dir / name);
    ASSERT_FALSE(map);
    EXPECT_EQ(map.error().cause, MapFileError::UnsupportedFormat);
    EXPECT_NE(map.error().message.find(".exr, .hdr or .pfm"), std::string::npos)
        << map.error().message;
    EXPECT_EQ(saveMap(patternMap(4, 2), dir / name).error().cause, MapFileError::UnsupportedFormat);
  }
}

TEST(MapFileErrors, TruncatedFilesAreErrorsNotCrashes) {
  const TempDir dir;
  const fs::path shared = fs::path(VEM_SHARED_DATA_DIR) / "hdri" / "park.exr";
  std::map<std::string, std::string> whole;
  if (fs::exists(shared)) whole["real.exr"] = readFile(shared);
  for (const char* name : {"saved.exr", "saved.hdr", "saved.pfm"}) {
    ASSERT_TRUE(saveMap(patternMap(64, 32), dir / name));
    whole[name] = readFile(dir / name);
  }
  for (const auto& [name, bytes] : whole)
    for (std::size_t keep : {std::size_t{0}, std::size_t{8}, bytes.size() / 2, bytes.size() - 9}) {
      SCOPED_TRACE(name + " cut to " + std::to_string(keep) + " bytes");
      writeFile(dir / ("cut-" + name), bytes.substr(0, keep));
      const auto map = loadMap(dir / ("cut-" + name));
      ASSERT_FALSE(map);
      EXPECT_EQ(map.error().cause, MapFileError::BadContents) << map.error().message;
    }
}

TEST(MapFileErrors, GarbageWithAMapNameIsAnErrorNotACrash) {
  const TempDir dir;
  std::mt19937 random(7);
  for (const auto& [name, signature] : {std::pair{"garbage.exr", ""},
                                        {"garbage.hdr", ""},
                                        {"garbage.pfm", ""},
                                        {"signed.exr", "\x76\x2f\x31\x01"},
                                        {"signed.hdr", "#?RADIANCE\n"},
                                        {"signed.pfm", "PF\n"}}) {
    for (int trial = 0; trial < 20; ++trial) {
      std::string bytes = signature;
      for (int i = 0; i < 2000; ++i) bytes += char(random() & 0xff);
      writeFile(dir / name, bytes);
      const auto map = loadMap(dir / name);
      ASSERT_FALSE(map) << name << " trial " << trial;
      EXPECT_EQ(map.error().cause, MapFileError::BadContents) << map.error().message;
    }
  }
}

TEST(MapFileErrors, EmptyOrAbsurdSizeInTheHeaderIsRefused) {
  const TempDir dir;
  for (const auto& [header, size] :
       {std::pair{"PF\n100000 50000\n-1.0\n", "100000 x 50000"}, {"PF\n0 0\n-1.0\n", ""}}) {
    writeFile(dir / "size.pfm", header);
    const auto map = loadMap(dir / "size.pfm");
    ASSERT_FALSE(map) << header;
    EXPECT_EQ(map.error().cause, MapFileError::BadContents);
    EXPECT_NE(map.error().message.find(size), std::string::npos) << map.error().message;
  }
}

// The process may write at most `bytes` bytes per file while this lives (SIGXFSZ ignored).
class FileSizeLimit {
 public:
  explicit FileSizeLimit(rlim_t bytes) : oldHandler_(std::signal(SIGXFSZ, SIG_IGN)) {
    ::getrlimit(RLIMIT_FSIZE, &old_);
    const rlimit limit{bytes, old_.rlim_max};
    ::setrlimit(RLIMIT_FSIZE, &limit);
  }
  FileSizeLimit(const FileSizeLimit&) = delete;
  FileSizeLimit& operator=(const FileSizeLimit&) = delete;
  ~FileSizeLimit() {
    ::setrlimit(RLIMIT_FSIZE, &old_);
    std::signal(SIGXFSZ, oldHandler_);
  }

 private:
  rlimit old_{};
  void (*oldHandler_)(int);
};

TEST(MapFileSave, FailedSaveLeavesTheExistingFileIntactAndNoTemporaryFile) {
  const TempDir dir;
  EnvMap big = EnvMap::filled(MapLayout::Sphere, 256, 128, glm::vec3(0));
  std::mt19937 random(3);
  for (float& v : big.rgb)
    v = std::uniform_real_distribution<float>(0, 1)(random);  // incompressible
  for (const char* name : {"keep.exr", "keep.pfm", "keep.hdr"}) {
    SCOPED_TRACE(name);
    ASSERT_TRUE(saveMap(patternMap(4, 2), dir / name));
    const std::string before = readFile(dir / name);
    std::expected<void, MapFileFailure> saved;
    {
      const FileSizeLimit limit(before.size() + 100);  // the old file fits, the new one does not
      saved = saveMap(big, dir / name);
    }
    ASSERT_FALSE(saved);
    EXPECT_EQ(saved.error().cause, MapFileError::WriteFailed);
    EXPECT_NE(saved.error().message.find(name), std::string::npos) << saved.error().message;
    EXPECT_EQ(readFile(dir / name), before);
  }
  EXPECT_EQ(std::distance(fs::directory_iterator(dir.path()), fs::directory_iterator{}), 3);
}

TEST(MapFileSave, MissingFolderIsWriteFailed) {
  const TempDir dir;
  const auto saved = saveMap(patternMap(4, 2), dir / "absent" / "map.exr");
  ASSERT_FALSE(saved);
  EXPECT_EQ(saved.error().cause, MapFileError::WriteFailed);
}

}  // namespace
}  // namespace vem::mapio
