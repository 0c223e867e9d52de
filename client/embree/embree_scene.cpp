#include "client/embree/embree_scene.h"

#include <algorithm>
#include <cstring>
#include <utility>

#include <embree3/rtcore.h>
#include <fmt/format.h>
#include <glm/glm.hpp>

namespace vem::embree {
namespace {

const char* errorName(RTCError error) {
  switch (error) {
    case RTC_ERROR_NONE: return "no error";
    case RTC_ERROR_UNKNOWN: return "unknown error";
    case RTC_ERROR_INVALID_ARGUMENT: return "invalid argument";
    case RTC_ERROR_INVALID_OPERATION: return "invalid operation";
    case RTC_ERROR_OUT_OF_MEMORY: return "out of memory";
    case RTC_ERROR_UNSUPPORTED_CPU: return "unsupported CPU";
    case RTC_ERROR_CANCELLED: return "cancelled";
  }
  return "unrecognised error";
}

// The device's pending error as a sentence, or empty.
std::string deviceError(RTCDevice device, const char* step) {
  const RTCError error = rtcGetDeviceError(device);
  if (error == RTC_ERROR_NONE) {
    return {};
  }
  return fmt::format("Embree failed to {}: {}.", step, errorName(error));
}

// Copies one mesh into a new triangle geometry attached as `geomId`.
std::string attachMesh(RTCDevice device, RTCScene scene, const scene::Mesh& mesh,
                       unsigned int geomId) {
  RTCGeometry geometry = rtcNewGeometry(device, RTC_GEOMETRY_TYPE_TRIANGLE);
  if (geometry == nullptr) {
    return deviceError(device, "create a triangle geometry");
  }
  void* vertices = rtcSetNewGeometryBuffer(geometry, RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT3,
                                           sizeof(glm::vec3), mesh.positions.size());
  void* indices = rtcSetNewGeometryBuffer(geometry, RTC_BUFFER_TYPE_INDEX, 0, RTC_FORMAT_UINT3,
                                          3 * sizeof(std::uint32_t), mesh.triangleCount());
  if (vertices == nullptr || indices == nullptr) {
    rtcReleaseGeometry(geometry);
    return deviceError(device, fmt::format("allocate the buffers of mesh '{}'", mesh.name).c_str());
  }
  std::memcpy(vertices, mesh.positions.data(), mesh.positions.size() * sizeof(glm::vec3));
  std::memcpy(indices, mesh.indices.data(), mesh.indices.size() * sizeof(std::uint32_t));
  rtcCommitGeometry(geometry);
  rtcAttachGeometryByID(scene, geometry, geomId);
  rtcReleaseGeometry(geometry);  // the scene holds it now
  return deviceError(device, fmt::format("attach mesh '{}'", mesh.name).c_str());
}

}  // namespace

void EmbreeScene::DeviceRelease::operator()(RTCDeviceTy* device) const { rtcReleaseDevice(device); }
void EmbreeScene::SceneRelease::operator()(RTCSceneTy* scene) const { rtcReleaseScene(scene); }

std::expected<EmbreeScene, std::string> EmbreeScene::build(const scene::Scene& scene,
                                                           const std::string& deviceConfig) {
  if (const std::string broken = scene::firstContractViolation(scene); !broken.empty()) {
    return std::unexpected(fmt::format("Scene '{}' cannot be ray traced: {}", scene.name, broken));
  }
  EmbreeScene out;
  out.device_.reset(rtcNewDevice(deviceConfig.empty() ? nullptr : deviceConfig.c_str()));
  if (!out.device_) {
    return std::unexpected(deviceError(nullptr, "create a device"));
  }
  out.scene_.reset(rtcNewScene(out.device_.get()));
  if (!out.scene_) {
    return std::unexpected(deviceError(out.device_.get(), "create a scene"));
  }
  for (std::size_t i = 0; i < scene.meshes.size(); ++i) {
    const scene::Mesh& mesh = scene.meshes[i];
    out.meshes_.push_back({mesh.positions, mesh.normals, mesh.indices, mesh.material});
    if (mesh.triangleCount() == 0) {
      continue;  // no geometry; the id stays free
    }
    const std::string error =
        attachMesh(out.device_.get(), out.scene_.get(), mesh, static_cast<unsigned int>(i));
    if (!error.empty()) {
      return std::unexpected(error);
    }
  }
  rtcCommitScene(out.scene_.get());
  if (std::string error = deviceError(out.device_.get(), "build the BVH"); !error.empty()) {
    return std::unexpected(std::move(error));
  }
  out.materials_ = scene.materials;
  const scene::Bounds bounds = scene::sceneBounds(scene);
  out.epsilon_ = kRelativeEpsilon * std::max(1.0F, bounds.radius());
  return out;
}

std::optional<SurfaceHit> EmbreeScene::intersect(const scene::Ray& ray, float tNear,
                                                 float tFar) const {
  RTCIntersectContext context;
  rtcInitIntersectContext(&context);
  RTCRayHit rayHit{};
  rayHit.ray.org_x = ray.originWorld.x;
  rayHit.ray.org_y = ray.originWorld.y;
  rayHit.ray.org_z = ray.originWorld.z;
  rayHit.ray.dir_x = ray.dirWorld.x;
  rayHit.ray.dir_y = ray.dirWorld.y;
  rayHit.ray.dir_z = ray.dirWorld.z;
  rayHit.ray.tnear = tNear;
  rayHit.ray.tfar = tFar;
  rayHit.ray.mask = 0xFFFFFFFFU;
  rayHit.hit.geomID = RTC_INVALID_GEOMETRY_ID;
  rayHit.hit.instID[0] = RTC_INVALID_GEOMETRY_ID;
  rtcIntersect1(scene_.get(), &context, &rayHit);
  if (rayHit.hit.geomID == RTC_INVALID_GEOMETRY_ID) {
    return std::nullopt;
  }
  return surfaceHit(rayHit.hit.geomID, rayHit.hit.primID, rayHit.hit.u, rayHit.hit.v, ray,
                    rayHit.ray.tfar);
}

bool EmbreeScene::occluded(glm::vec3 originWorld, glm::vec3 dirWorld, float tNear,
                           float tFar) const {
  RTCIntersectContext context;
  rtcInitIntersectContext(&context);
  RTCRay ray{};
  ray.org_x = originWorld.x;
  ray.org_y = originWorld.y;
  ray.org_z = originWorld.z;
  ray.dir_x = dirWorld.x;
  ray.dir_y = dirWorld.y;
  ray.dir_z = dirWorld.z;
  ray.tnear = tNear;
  ray.tfar = tFar;
  ray.mask = 0xFFFFFFFFU;
  rtcOccluded1(scene_.get(), &context, &ray);
  return ray.tfar < 0.0F;  // Embree sets tfar to -inf on a hit
}

SurfaceHit EmbreeScene::surfaceHit(std::uint32_t geomId, std::uint32_t primId, float u, float v,
                                   const scene::Ray& ray, float t) const {
  const MeshData& mesh = meshes_[geomId];
  const std::uint32_t* tri = &mesh.indices[3 * std::size_t(primId)];
  const glm::vec3 p0 = mesh.positions[tri[0]];
  const glm::vec3 p1 = mesh.positions[tri[1]];
  const glm::vec3 p2 = mesh.positions[tri[2]];
  SurfaceHit hit;
  hit.distance = t;
  hit.positionWorld = ray.originWorld + t * ray.dirWorld;
  const glm::vec3 ng = glm::cross(p1 - p0, p2 - p0);
  const float ngLength = glm::length(ng);
  hit.geometricNormal = ngLength > 0.0F ? ng / ngLength : -ray.dirWorld;
  const glm::vec3 ns =
      (1.0F - u - v) * mesh.normals[tri[0]] + u * mesh.normals[tri[1]] + v * mesh.normals[tri[2]];
  const float nsLength = glm::length(ns);
  hit.shadingNormal = nsLength > 1e-6F ? ns / nsLength : hit.geometricNormal;
  hit.meshIndex = geomId;
  hit.materialIndex = mesh.material;
  return hit;
}

glm::vec3 offsetOrigin(const SurfaceHit& hit, glm::vec3 dirWorld, float epsilon) {
  const float side = glm::dot(hit.geometricNormal, dirWorld) >= 0.0F ? 1.0F : -1.0F;
  return hit.positionWorld + (side * epsilon) * hit.geometricNormal;
}

}  // namespace vem::embree
