# Every dependency comes from Debian's packages (see cmake/deps.sh) and is found here, once.
find_package(PkgConfig REQUIRED)
find_package(glm REQUIRED)                       # libglm-dev: vector maths
pkg_check_modules(NANOFLANN REQUIRED IMPORTED_TARGET nanoflann)   # libnanoflann-dev: kd-tree
find_package(OpenEXR REQUIRED)                   # libopenexr-dev: .exr maps
find_package(Imath REQUIRED)                     # libimath-dev (with OpenEXR): half floats on the wire
find_package(OpenCV REQUIRED COMPONENTS core imgcodecs imgproc calib3d photo videoio)  # libopencv-dev:
                                                 # map and frame files, calibration maths
find_package(CLI11 REQUIRED)                     # libcli11-dev: argument parsing
find_package(tomlplusplus REQUIRED)              # libtomlplusplus-dev: calibration and config files
find_package(nlohmann_json REQUIRED)             # nlohmann-json3-dev: JSON output
find_package(spdlog REQUIRED)                    # libspdlog-dev: logging in the shells
find_package(Protobuf REQUIRED)                  # libprotobuf-dev, protobuf-compiler: record metadata
find_package(Boost REQUIRED)                     # libboost-dev (headers): Boost.CRC, the CRC32C oracle,
                                                 # Boost.Beast and Asio (the stream's WebSocket)
# Every unit that includes Beast sees the same string_view (std's): Beast's header-only classes
# differ in layout between the two, and a program that links units compiled both ways breaks the
# one-definition rule (the server's HTTP parser crashed in a test that linked a test client
# compiled without it).
add_compile_definitions(BOOST_BEAST_USE_STD_STRING_VIEW)
pkg_check_modules(ZSTD REQUIRED IMPORTED_TARGET libzstd)   # libzstd-dev: recorded pixels
pkg_check_modules(ISAL REQUIRED IMPORTED_TARGET libisal)   # libisal-dev: fast CRC32C of records
pkg_check_modules(SYSTEMD REQUIRED IMPORTED_TARGET libsystemd)  # libsystemd-dev: vemd's sd_notify
pkg_check_modules(MOSQUITTO REQUIRED IMPORTED_TARGET libmosquitto)  # libmosquitto-dev: MQTT (vemd publishes, clients subscribe)

# liquid-dsp (libliquid-dev) ships a static library and a header, without CMake or pkg-config files.
find_path(LIQUID_INCLUDE_DIR liquid/liquid.h REQUIRED)
find_library(LIQUID_LIBRARY NAMES liquid REQUIRED)
add_library(liquid::liquid UNKNOWN IMPORTED)
set_target_properties(liquid::liquid PROPERTIES IMPORTED_LOCATION "${LIQUID_LIBRARY}"
                      INTERFACE_INCLUDE_DIRECTORIES "${LIQUID_INCLUDE_DIR}"
                      INTERFACE_LINK_LIBRARIES m)

if(VEM_BUILD_TESTS)
  find_package(GTest REQUIRED)
endif()
if(VEM_BUILD_BENCHMARKS)
  find_package(benchmark REQUIRED)
endif()
find_package(fmt REQUIRED)                       # libfmt-dev (with spdlog): formatting in the shells
find_package(OpenSSL REQUIRED)                   # libssl-dev: TLS (wss://) for vemd's stream server

# vemview, the render client (client/): scenes, the OpenGL and the Embree renderers.
find_package(tinyobjloader REQUIRED)             # libtinyobjloader-dev: OBJ scenes
find_package(TinyGLTF REQUIRED)                  # libtinygltf-dev: glTF 2.0 scenes
find_package(embree 3 REQUIRED)                  # libembree-dev: the CPU (ray-traced) renderer
find_package(TBB REQUIRED)                       # libtbb-dev (Embree uses it too): its rows in parallel
find_package(glfw3 REQUIRED)                     # libglfw3-dev: vemview's window
pkg_check_modules(EPOXY REQUIRED IMPORTED_TARGET epoxy)  # libepoxy-dev: GL and EGL entry points
pkg_check_modules(EGL REQUIRED IMPORTED_TARGET egl)      # libegl-dev: headless GL contexts
