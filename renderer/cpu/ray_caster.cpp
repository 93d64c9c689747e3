#include "cpu/ray_caster.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <string>

#include <embree3/rtcore.h>

#include "common/error.hpp"
#include "kernels/shared.hpp"
#include "scene/mesh_check.hpp"
#include "scene/plane_frame.hpp"

namespace facet {

namespace {

bool finite(const glm::dvec3& v) { return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z); }

// The smallest float >= x, so a float interval never cuts off a double one.
float float_at_least(double x) {
  const float f = static_cast<float>(x);
  return static_cast<double>(f) < x ? std::nextafter(f, std::numeric_limits<float>::infinity()) : f;
}

RTCRay embree_ray(const glm::dvec3& o, const glm::dvec3& d, double t_max) {
  RTCRay ray{};
  ray.org_x = static_cast<float>(o.x);
  ray.org_y = static_cast<float>(o.y);
  ray.org_z = static_cast<float>(o.z);
  ray.dir_x = static_cast<float>(d.x);
  ray.dir_y = static_cast<float>(d.y);
  ray.dir_z = static_cast<float>(d.z);
  ray.tnear = 0.0f;
  ray.tfar = float_at_least(t_max);
  ray.mask = 0xFFFFFFFFu;
  ray.flags = 0;
  return ray;
}

// Turns the normals toward the side the ray comes from (see ray_caster.hpp).
void face_toward_ray(Hit& hit, const glm::dvec3& d) {
  if (glm::dot(hit.geometric_normal, d) > 0.0) hit.geometric_normal = -hit.geometric_normal;
  hit.back_face = glm::dot(hit.shading_normal, hit.geometric_normal) < 0.0;
  if (hit.back_face) hit.shading_normal = -hit.shading_normal;
}

// Whether a point of a finite plane lies on its rectangle (scene.hpp, Plane::size).
bool inside_rectangle(const Plane& plane, const PlaneFrame& frame, const glm::dvec3& position) {
  const glm::dvec3 r = position - plane.point;
  return std::abs(glm::dot(r, frame.tangent)) <= 0.5 * plane.size->x &&
         std::abs(glm::dot(r, frame.bitangent)) <= 0.5 * plane.size->y;
}

struct AnalyticHit {
  double t = -1.0;
  bool is_sphere = false;
  size_t index = 0;
};

AnalyticHit nearest_analytic(const Scene& scene, const std::vector<PlaneFrame>& frames, const glm::dvec3& o,
                             const glm::dvec3& d, double t_max) {
  using namespace kernels::f64;
  AnalyticHit best;
  double limit = t_max;
  for (size_t i = 0; i < scene.planes.size(); ++i) {
    const Plane& p = scene.planes[i];
    const double t = intersect_plane(o, d, p.point, p.normal, 0.0, limit);
    if (t > 0.0 && (!p.size || inside_rectangle(p, frames[i], o + t * d))) best = {limit = t, false, i};
  }
  for (size_t i = 0; i < scene.spheres.size(); ++i) {
    const double t = intersect_sphere(o, d, scene.spheres[i].center, scene.spheres[i].radius, 0.0, limit);
    if (t > 0.0) best = {limit = t, true, i};
  }
  return best;
}

Hit analytic_hit(const Scene& scene, const std::vector<PlaneFrame>& frames, const AnalyticHit& a, const glm::dvec3& o,
                 const glm::dvec3& d) {
  Hit hit{};
  hit.t = a.t;
  if (a.is_sphere) {
    const Sphere& s = scene.spheres[a.index];
    const glm::dvec3 n = glm::normalize(o + a.t * d - s.center);
    hit.position = s.center + s.radius * n;  // back onto the surface
    hit.geometric_normal = n;
    // u: longitude about +y from +z, v: polar angle from +y, both in [0, 1].
    hit.uv = {0.5 + std::atan2(n.x, n.z) * (0.5 * std::numbers::inv_pi),
              std::acos(glm::clamp(n.y, -1.0, 1.0)) * std::numbers::inv_pi};
    hit.dpdu = 2.0 * std::numbers::pi * s.radius * glm::dvec3(n.z, 0.0, -n.x);
    hit.material = s.material;
  } else {
    const Plane& p = scene.planes[a.index];
    hit.position = o + a.t * d;
    const PlaneFrame& frame = frames[a.index];  // unit normal: from the loader, not always from code
    hit.geometric_normal = frame.normal;
    hit.uv =
        glm::dvec2(glm::dot(hit.position - p.point, frame.tangent), glm::dot(hit.position - p.point, frame.bitangent)) *
        p.uv_scale;
    hit.dpdu = frame.tangent / p.uv_scale.x;
    hit.material = p.material;
  }
  hit.shading_normal = hit.geometric_normal;
  face_toward_ray(hit, d);
  return hit;
}

// Re-intersects Embree's triangle in double (Moller-Trumbore); Embree's float barycentrics
// and t are the fallback when the double test degenerates (det == 0).
Hit mesh_hit(const Mesh& mesh, uint32_t triangle, const RTCHit& h, float t_float, const glm::dvec3& o,
             const glm::dvec3& d) {
  const uint32_t i0 = mesh.indices[3 * triangle], i1 = mesh.indices[3 * triangle + 1],
                 i2 = mesh.indices[3 * triangle + 2];
  const glm::dvec3 p0 = mesh.positions[i0], e1 = mesh.positions[i1] - p0, e2 = mesh.positions[i2] - p0;
  double b1 = h.u, b2 = h.v, t = t_float;
  const glm::dvec3 pvec = glm::cross(d, e2);
  const double det = glm::dot(e1, pvec);
  if (det != 0.0) {
    const glm::dvec3 tvec = o - p0, qvec = glm::cross(tvec, e1);
    b1 = glm::dot(tvec, pvec) / det;
    b2 = glm::dot(d, qvec) / det;
    // Embree found t > 0 in float; a ray starting on the triangle may round to t <= 0 here.
    t = std::max(glm::dot(e2, qvec) / det, std::numeric_limits<double>::denorm_min());
  }
  // Embree decided the hit in float; keep the refined point inside the triangle.
  b1 = glm::clamp(b1, 0.0, 1.0);
  b2 = glm::clamp(b2, 0.0, 1.0 - b1);
  const double b0 = 1.0 - b1 - b2;

  Hit hit{};
  hit.t = t;
  hit.position = p0 + b1 * e1 + b2 * e2;
  const glm::dvec3 face = glm::cross(e1, e2);
  hit.geometric_normal = glm::length(face) > 0.0 ? glm::normalize(face) : -d;
  hit.shading_normal = hit.geometric_normal;
  if (!mesh.normals.empty()) {
    const glm::dvec3 n = b0 * mesh.normals[i0] + b1 * mesh.normals[i1] + b2 * mesh.normals[i2];
    if (glm::length(n) > 1e-12) hit.shading_normal = glm::normalize(n);  // opposite normals can cancel
  }
  hit.uv = mesh.uvs.empty() ? glm::dvec2(b1, b2) : b0 * mesh.uvs[i0] + b1 * mesh.uvs[i1] + b2 * mesh.uvs[i2];
  // dp = e1 db1 + e2 db2 and duv = duv1 db1 + duv2 db2: invert the triangle's uv Jacobian (without
  // uvs, u = b1 and dp/du = e1).
  const glm::dvec2 duv1 = mesh.uvs.empty() ? glm::dvec2(1, 0) : mesh.uvs[i1] - mesh.uvs[i0];
  const glm::dvec2 duv2 = mesh.uvs.empty() ? glm::dvec2(0, 1) : mesh.uvs[i2] - mesh.uvs[i0];
  const double uv_det = duv1.x * duv2.y - duv1.y * duv2.x;
  if (std::abs(uv_det) > 1e-20) hit.dpdu = (duv2.y * e1 - duv1.y * e2) / uv_det;
  hit.material = mesh.material;
  face_toward_ray(hit, d);
  return hit;
}

}  // namespace

struct RayCaster::Embree {
  RTCDevice device = nullptr;
  RTCScene scene = nullptr;

  ~Embree() {
    if (scene != nullptr) rtcReleaseScene(scene);
    if (device != nullptr) rtcReleaseDevice(device);
  }
};

RayCaster::RayCaster(const Scene& scene) : scene_(scene), embree_(std::make_unique<Embree>()) {
  for (const Plane& p : scene.planes) plane_frames_.push_back(plane_frame(p));
  embree_->device = rtcNewDevice(nullptr);
  if (embree_->device == nullptr) {
    throw Error("cannot create the Embree device (error " + std::to_string(rtcGetDeviceError(nullptr)) + ")");
  }
  embree_->scene = rtcNewScene(embree_->device);
  rtcSetSceneFlags(embree_->scene, RTC_SCENE_FLAG_ROBUST);  // watertight: no rays through shared edges
  rtcSetSceneBuildQuality(embree_->scene, RTC_BUILD_QUALITY_HIGH);
  for (size_t m = 0; m < scene.meshes.size(); ++m) {
    const Mesh& mesh = scene.meshes[m];
    check_mesh(mesh);  // the queries index vertices and attributes without further checks
    if (mesh.triangle_count() == 0) continue;
    RTCGeometry geometry = rtcNewGeometry(embree_->device, RTC_GEOMETRY_TYPE_TRIANGLE);
    auto* vertices = static_cast<float*>(rtcSetNewGeometryBuffer(geometry, RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT3,
                                                                 3 * sizeof(float), mesh.positions.size()));
    auto* indices = static_cast<uint32_t*>(rtcSetNewGeometryBuffer(geometry, RTC_BUFFER_TYPE_INDEX, 0, RTC_FORMAT_UINT3,
                                                                   3 * sizeof(uint32_t), mesh.triangle_count()));
    if (vertices == nullptr || indices == nullptr) {
      rtcReleaseGeometry(geometry);
      throw Error("cannot allocate Embree buffers for mesh " + mesh.name);
    }
    for (size_t v = 0; v < mesh.positions.size(); ++v) {
      for (int k = 0; k < 3; ++k) vertices[3 * v + static_cast<size_t>(k)] = static_cast<float>(mesh.positions[v][k]);
    }
    std::copy(mesh.indices.begin(), mesh.indices.begin() + static_cast<std::ptrdiff_t>(3 * mesh.triangle_count()),
              indices);
    rtcCommitGeometry(geometry);
    rtcAttachGeometryByID(embree_->scene, geometry, static_cast<unsigned>(m));  // geomID = mesh index
    rtcReleaseGeometry(geometry);
  }
  rtcCommitScene(embree_->scene);
  if (const RTCError e = rtcGetDeviceError(embree_->device); e != RTC_ERROR_NONE) {
    throw Error("Embree failed to build the scene (error " + std::to_string(e) + ")");
  }
}

RayCaster::~RayCaster() = default;

std::optional<Hit> RayCaster::intersect(glm::dvec3 o, glm::dvec3 d, double t_max) const {
  if (!finite(o) || !finite(d) || std::isnan(t_max) || !(t_max > 0.0)) return std::nullopt;
  const AnalyticHit analytic = nearest_analytic(scene_, plane_frames_, o, d, t_max);
  const double limit = analytic.t > 0.0 ? analytic.t : t_max;

  if (scene_.meshes.empty()) {  // Embree has nothing to add: skip its call (most of a plane query's cost)
    if (analytic.t > 0.0) return analytic_hit(scene_, plane_frames_, analytic, o, d);
    return std::nullopt;
  }
  RTCIntersectContext context;
  rtcInitIntersectContext(&context);
  RTCRayHit ray_hit{};
  ray_hit.ray = embree_ray(o, d, limit);
  ray_hit.hit.geomID = RTC_INVALID_GEOMETRY_ID;
  rtcIntersect1(embree_->scene, &context, &ray_hit);

  std::optional<Hit> best;
  if (analytic.t > 0.0) best = analytic_hit(scene_, plane_frames_, analytic, o, d);
  if (ray_hit.hit.geomID != RTC_INVALID_GEOMETRY_ID) {
    const Hit mesh =
        mesh_hit(scene_.meshes[ray_hit.hit.geomID], ray_hit.hit.primID, ray_hit.hit, ray_hit.ray.tfar, o, d);
    if (!best || mesh.t < best->t) best = mesh;
  }
  return best;
}

bool RayCaster::occluded(glm::dvec3 o, glm::dvec3 d, double t_max) const {
  if (!finite(o) || !finite(d) || std::isnan(t_max) || !(t_max > 0.0)) return false;
  if (nearest_analytic(scene_, plane_frames_, o, d, t_max).t > 0.0) return true;
  if (scene_.meshes.empty()) return false;
  RTCIntersectContext context;
  rtcInitIntersectContext(&context);
  RTCRay ray = embree_ray(o, d, t_max);
  rtcOccluded1(embree_->scene, &context, &ray);
  return ray.tfar < 0.0f;  // Embree marks an occluded ray with tfar = -inf
}

}  // namespace facet
