// Timings of VEM recordings (daemon/recording): reading one recorded 1280 x 1024 Mono16 frame
// (pread, CRC32C, metadata, zstd decompression, byte planes back to codes) and recording one
// (planes, zstd at the default level, CRC32C, one write into the page cache, no fdatasync), on a
// frame from the camera simulator. Also zstd levels side by side ("recording/compress_level_<L>",
// with the compression ratio as a counter), which chose kDefaultZstdLevel.
// Registered as "recording/<name>".
#pragma once

namespace vem::bench {

void registerRecordingBenchmarks();

}  // namespace vem::bench
