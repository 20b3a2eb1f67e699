#include "intersect/embree_intersector.h"

#include <embree3/rtcore.h>

#include <cmath>
#include <limits>
#include <string>

#include "util/error.h"

namespace facetlight {

EmbreeIntersector::EmbreeIntersector(const Stone& stone) {
    if (stone.triangles.empty()) throw Error("stone '" + stone.name + "' has no triangles");
    // One build thread: stone meshes are small, and the tracer's own threads are the parallelism.
    device_ = rtcNewDevice("threads=1");
    if (!device_)
        throw Error("cannot start Embree (error " + std::to_string(int(rtcGetDeviceError(nullptr))) + ")");
    scene_ = rtcNewScene(device_);
    rtcSetSceneBuildQuality(scene_, RTC_BUILD_QUALITY_HIGH);
    rtcSetSceneFlags(scene_, RTC_SCENE_FLAG_ROBUST);

    RTCGeometry geom = rtcNewGeometry(device_, RTC_GEOMETRY_TYPE_TRIANGLE);
    auto* v = static_cast<float*>(rtcSetNewGeometryBuffer(geom, RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT3,
                                                          3 * sizeof(float), stone.vertices.size()));
    auto* idx = static_cast<unsigned*>(rtcSetNewGeometryBuffer(
        geom, RTC_BUFFER_TYPE_INDEX, 0, RTC_FORMAT_UINT3, 3 * sizeof(unsigned), stone.triangles.size()));
    double radius = 0;
    for (size_t i = 0; i < stone.vertices.size(); ++i) {
        const Vec3& p = stone.vertices[i];
        v[3 * i] = float(p.x);
        v[3 * i + 1] = float(p.y);
        v[3 * i + 2] = float(p.z);
        radius = std::fmax(radius, length(p));
    }
    triangleFacet_.resize(stone.triangles.size());
    for (size_t i = 0; i < stone.triangles.size(); ++i) {
        for (int k = 0; k < 3; ++k) idx[3 * i + k] = stone.triangles[i].v[k];
        triangleFacet_[i] = stone.triangles[i].facet;
    }
    for (const Facet& f : stone.facets) facetNormal_.emplace_back(f.normal);
    rtcCommitGeometry(geom);
    rtcAttachGeometry(scene_, geom);
    rtcReleaseGeometry(geom);
    rtcCommitScene(scene_);
    if (rtcGetDeviceError(device_) != RTC_ERROR_NONE) {
        rtcReleaseScene(scene_);
        rtcReleaseDevice(device_);
        throw Error("Embree could not build the scene for stone '" + stone.name + "'");
    }
    selfHitEpsilon_ = float(1e-5 * radius);
}

EmbreeIntersector::~EmbreeIntersector() {
    rtcReleaseScene(scene_);
    rtcReleaseDevice(device_);
}

bool EmbreeIntersector::cast(const Vec3f& o, const Vec3f& d, float tnear, SurfaceHit& hit) const {
    RTCIntersectContext context;
    rtcInitIntersectContext(&context);
    RTCRayHit rh;
    rh.ray.org_x = o.x;
    rh.ray.org_y = o.y;
    rh.ray.org_z = o.z;
    rh.ray.dir_x = d.x;
    rh.ray.dir_y = d.y;
    rh.ray.dir_z = d.z;
    rh.ray.tnear = tnear;
    rh.ray.tfar = std::numeric_limits<float>::infinity();
    rh.ray.time = 0;
    rh.ray.mask = ~0u;
    rh.ray.id = 0;
    rh.ray.flags = 0;
    rh.hit.geomID = RTC_INVALID_GEOMETRY_ID;
    rh.hit.instID[0] = RTC_INVALID_GEOMETRY_ID;
    rtcIntersect1(scene_, &context, &rh);
    if (rh.hit.geomID == RTC_INVALID_GEOMETRY_ID) return false;
    hit = {rh.ray.tfar, triangleFacet_[rh.hit.primID]};
    return true;
}

bool EmbreeIntersector::enter(const Vec3f& o, const Vec3f& d, SurfaceHit& hit) const {
    return cast(o, d, 0.0f, hit) && dot(d, facetNormal_[hit.facet]) < 0;
}

bool EmbreeIntersector::leave(const Vec3f& o, const Vec3f& d, SurfaceHit& hit) const {
    // Start a little behind the point, so that a photon a rounding error outside the facet next to the one it
    // stands on still crosses it, and skip the crossings into the stone (the facet it stands on among them).
    const Vec3f start = o - d * selfHitEpsilon_;
    float tnear = 0;
    for (int attempt = 0; attempt < 8; ++attempt) {
        if (!cast(start, d, tnear, hit)) return false;
        if (dot(d, facetNormal_[hit.facet]) > 0) {
            hit.t = std::fmax(hit.t - selfHitEpsilon_, 0.0f);
            return true;
        }
        tnear = std::nextafter(hit.t, std::numeric_limits<float>::infinity());
    }
    return false;
}

}  // namespace facetlight
