// The packet walk: sixteen photons inside a convex stone, one per AVX-512 lane, stepped together. A step is
// the one-photon step() done lane-wise (the same operations in the same order, so the same bits), with
// masks where step() branches: the reflect-or-refract draw no longer costs a mispredicted branch per
// interaction, and the exit search tests one plane against sixteen rays at a time. Photons are started
// sixteen at a time too where the light is one collimated beam at one index of refraction. A lane whose
// photon is done takes the next started photon, so the lanes stay full until the block runs out.
#include "trace/detail/photon_walker.h"

#if FACETLIGHT_PACKETS

#include <array>
#include <bit>
#include <limits>

namespace facetlight {

constexpr int kLanes = 16;

// Photons inside the stone, one per lane, as a structure of arrays.
struct alignas(64) PhotonWalker::Packet {
    float px[kLanes]{}, py[kLanes]{}, pz[kLanes]{};
    float dx[kLanes]{}, dy[kLanes]{}, dz[kLanes]{};
    float n[kLanes]{};
    uint64_t rng[kLanes]{};
    uint32_t bounces[kLanes]{};
    LaneMask live = 0;

    void put(int k, const Vec3f& p, const Vec3f& d, float index, uint64_t rngState) {
        px[k] = p.x, py[k] = p.y, pz[k] = p.z;
        dx[k] = d.x, dy[k] = d.y, dz[k] = d.z;
        n[k] = index;
        rng[k] = rngState;
        bounces[k] = 0;
        live |= LaneMask(1u << k);
    }
    // Lane k takes the photon in lane j of another packet.
    void take(int k, const Packet& from, int j) {
        put(k, {from.px[j], from.py[j], from.pz[j]}, {from.dx[j], from.dy[j], from.dz[j]}, from.n[j],
            from.rng[j]);
    }
};

namespace {

// What one step found, per lane, for the tallies that follow it.
struct alignas(64) StepResult {
    float px[kLanes], py[kLanes], pz[kLanes];
    float cosI[kLanes], cosT[kLanes];
    uint32_t facet[kLanes];
};

// Calls f(lane) for each lane set in the mask.
template <class F>
inline void forEachLane(LaneMask mask, F&& f) {
    for (unsigned m = mask; m; m &= m - 1) f(std::countr_zero(m));
}

// std::clamp(v, 0, 1) lane-wise, NaN kept as it is.
inline Floats16 clampUnit(Floats16 v) {
    const Floats16 zero(0.0f), one(1.0f);
    return select(v < zero, zero, select(one < v, one, v));
}

// The normal of each lane's facet.
inline std::array<Floats16, 3> gatherNormals(const std::vector<Vec3f>& normal, __m512i facet) {
    const float* x = &normal[0].x;
    const __m512i at = _mm512_add_epi32(facet, _mm512_slli_epi32(facet, 1));  // 3 floats per normal
    return {_mm512_i32gather_ps(at, x, 4), _mm512_i32gather_ps(at, x + 1, 4),
            _mm512_i32gather_ps(at, x + 2, 4)};
}

constexpr float kInf = std::numeric_limits<float>::infinity();

}  // namespace

void PhotonWalker::packets(const Scene& s, uint64_t begin, uint64_t end, Tally& tally) {
    Packet lanes, started;  // started: photons inside the stone, waiting for a lane
    uint64_t next = begin;
    for (;;) {
        for (unsigned empty = LaneMask(~lanes.live); empty;) {
            if (!started.live) {
                if (next >= end) break;
                startPacket(s, next, end, tally, started);
                next += kLanes;
                continue;
            }
            lanes.take(std::countr_zero(empty), started, std::countr_zero(unsigned(started.live)));
            started.live &= started.live - 1;
            empty &= empty - 1;
        }
        if (!lanes.live) return;
        stepPacket(s, lanes, tally);
    }
}

void PhotonWalker::startPacket(const Scene& s, uint64_t first, uint64_t end, Tally& tally,
                               Packet& started) {
    const uint64_t count = std::min<uint64_t>(kLanes, end - first);
    if (!s.beam_) {
        int k = 0;
        for (uint64_t i = first; i < first + count; ++i) {
            Photon ph;
            if (start(s, *s.convex_, i, tally, ph)) started.put(k++, ph.p, ph.d, ph.n, ph.rng.state());
        }
        return;
    }
    // One collimated beam: start() lane-wise.
    const LaneMask lanes = count == kLanes ? LaneMask(0xffff) : LaneMask((1u << count) - 1);
    seedOf(s.settings_.seed, first, started.rng);
    Floats16 ox, oy, oz;
    s.light_.sampleBeam(started.rng, ox, oy, oz);
    Floats16 n(s.fixedIndex_);
    if (s.dispersive()) {
        const Floats16 wavelength = Floats16(380.0f) + Floats16(400.0f) * uniformOf(started.rng, lanes);
        n = viaDoubles(wavelength, [&](Doubles8 w) { return s.material_.index(w); });
    }
    Floats16 t;
    __m512i facet;
    const LaneMask hits = lanes & s.beam_->enter(ox, oy, oz, t, facet);
    const Vec3f d(s.light_.direction());
    const Floats16 dx(d.x), dy(d.y), dz(d.z);
    const auto [nx, ny, nz] = gatherNormals(s.normal_, facet);
    const Floats16 cosI = clampUnit(-(dx * nx + dy * ny + dz * nz)), eta = Floats16(1.0f) / n;
    const FresnelTerms<Floats16> fr = fresnelTerms(cosI, eta);
    const LaneMask reflects = hits & (uniformOf(started.rng, hits) < fr.reflectance);

    StepResult hit;
    (ox + dx * t).store(hit.px), (oy + dy * t).store(hit.py), (oz + dz * t).store(hit.pz);
    cosI.store(hit.cosI), fr.cosT.store(hit.cosT);
    _mm512_store_si512(hit.facet, facet);
    alignas(64) float index[kLanes], etas[kLanes];
    n.store(index), eta.store(etas);
    forEachLane(reflects, [&](int k) {
        const uint32_t f = hit.facet[k];
        tally.reflectedAtEntry(f, {hit.px[k], hit.py[k], hit.pz[k]},
                               reflectOff(d, s.normal_[f], hit.cosI[k]));
    });
    forEachLane(hits & LaneMask(~reflects), [&](int k) {
        const uint32_t f = hit.facet[k];
        tally.entered(f);
        started.put(k, {hit.px[k], hit.py[k], hit.pz[k]},
                    refractIn(d, s.normal_[f], etas[k], hit.cosI[k], hit.cosT[k]), index[k], started.rng[k]);
    });
}

void PhotonWalker::stepPacket(const Scene& s, Packet& lanes, Tally& tally) {
    const RayPacket ray{Floats16::load(lanes.px), Floats16::load(lanes.py), Floats16::load(lanes.pz),
                        Floats16::load(lanes.dx), Floats16::load(lanes.dy), Floats16::load(lanes.dz)};
    Floats16 t;
    __m512i facet;
    s.convex_->leave(ray, t, facet);
    const LaneMask live = lanes.live, inside = live & (t < Floats16(kInf));
    const Floats16 px = ray.ox + ray.dx * t, py = ray.oy + ray.dy * t, pz = ray.oz + ray.dz * t;
    const auto [nx, ny, nz] = gatherNormals(s.normal_, facet);
    const Floats16 cosI = clampUnit(ray.dx * nx + ray.dy * ny + ray.dz * nz);
    const FresnelTerms<Floats16> fr = fresnelTerms(cosI, Floats16::load(lanes.n));
    const LaneMask draw = inside & LaneMask(~fr.totalInternal);
    const LaneMask exits = draw & (uniformOf(lanes.rng, draw) >= fr.reflectance);
    const LaneMask reflects = inside & LaneMask(~exits);

    StepResult hit;
    px.store(hit.px), py.store(hit.py), pz.store(hit.pz);
    cosI.store(hit.cosI), fr.cosT.store(hit.cosT);
    _mm512_store_si512(hit.facet, facet);
    forEachLane(live & LaneMask(~inside), [&](int k) { tally.lost(lanes.bounces[k]); });
    forEachLane(exits, [&](int k) {
        const uint32_t f = hit.facet[k];
        const Vec3f d{lanes.dx[k], lanes.dy[k], lanes.dz[k]};
        tally.exited(f, {hit.px[k], hit.py[k], hit.pz[k]},
                     refractOut(d, s.normal_[f], lanes.n[k], hit.cosI[k], hit.cosT[k]), lanes.bounces[k]);
    });

    // The reflected photons go on from the hit point; each counts a bounce.
    const Floats16 twoCos = Floats16(2.0f) * cosI;
    (ray.dx - nx * twoCos).store(lanes.dx), (ray.dy - ny * twoCos).store(lanes.dy);
    (ray.dz - nz * twoCos).store(lanes.dz);
    px.store(lanes.px), py.store(lanes.py), pz.store(lanes.pz);
    __m512i bounces = _mm512_load_si512(lanes.bounces);
    bounces = _mm512_mask_add_epi32(bounces, reflects, bounces, _mm512_set1_epi32(1));
    _mm512_store_si512(lanes.bounces, bounces);
    const LaneMask trapped =
        _mm512_mask_cmpge_epu32_mask(reflects, bounces, _mm512_set1_epi32(s.settings_.maxBounces));
    forEachLane(reflects, [&](int k) { tally.internalReflection(hit.facet[k]); });
    forEachLane(trapped, [&](int k) { tally.trapped(lanes.bounces[k]); });
    lanes.live = reflects & LaneMask(~trapped);
}

}  // namespace facetlight

#endif
