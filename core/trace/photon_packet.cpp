// The packet walk: photons inside a convex stone, one per SIMD lane (4 with SSE4, 8 with AVX2, 16 with
// AVX-512), stepped together. A step is the one-photon step() done lane-wise (the same operations in the
// same order, so the same bits; a polarised trace's Stokes vectors too), with masks where step() branches:
// the reflect-or-refract draw no longer costs a mispredicted branch per interaction, and the exit search
// tests one plane against a packet of rays at a time. Photons are started a packet at a time too where the
// light is one collimated beam. A lane whose photon is done takes the next started photon, so the lanes stay
// full until the block runs out. Compiled once per SIMD target; the CPU's best is picked once per block of
// photons.
#include <algorithm>
#include <bit>

#include "trace/photon_walker.h"

#undef HWY_TARGET_INCLUDE
#define HWY_TARGET_INCLUDE "trace/photon_packet.cpp"
#include "hwy/foreach_target.h"  // IWYU pragma: keep

#include "hwy/highway.h"
#include "intersect/convex_search-inl.h"
#include "optics/uniaxial_interface-inl.h"
#include "util/lanes-inl.h"

HWY_BEFORE_NAMESPACE();
namespace facetlight {
namespace HWY_NAMESPACE {
#if HWY_TARGET != HWY_SCALAR
namespace {

constexpr size_t kMaxLanes = HWY_LANES(float);
using LaneBits = uint64_t;  // bit k: lane k
static_assert(kMaxLanes <= 64, "lane masks are 64-bit");

HWY_INLINE size_t laneCount() {
    return hn::Lanes(FloatTag());
}
HWY_INLINE LaneBits bitsOf(FloatMask m) {
    LaneBits bits = 0;
    hn::StoreMaskBits(FloatTag(), m, reinterpret_cast<uint8_t*>(&bits));
    return bits;
}
HWY_INLINE FloatMask maskOf(LaneBits bits) {
    return hn::LoadMaskBits(FloatTag(), reinterpret_cast<const uint8_t*>(&bits));
}

// Calls f(lane) for each lane set in the mask.
template <class F>
HWY_INLINE void forEachLane(LaneBits bits, F&& f) {
    for (; bits; bits &= bits - 1) f(std::countr_zero(bits));
}

// Photons' polarisation (PhotonWalker::Photon::pol), one per lane: Stokes vector and frame.
struct alignas(64) PolarizationLanes {
    float s0[kMaxLanes], s1[kMaxLanes], s2[kMaxLanes], s3[kMaxLanes];
    float xx[kMaxLanes], xy[kMaxLanes], xz[kMaxLanes];

    Polarization operator[](int k) const { return {{s0[k], s1[k], s2[k], s3[k]}, {xx[k], xy[k], xz[k]}}; }
    void put(int k, const Polarization& p) {
        s0[k] = p.stokes.s0, s1[k] = p.stokes.s1, s2[k] = p.stokes.s2, s3[k] = p.stokes.s3;
        xx[k] = p.x.x, xy[k] = p.x.y, xz[k] = p.x.z;
    }
    StokesOf<Floats> stokes() const {
        return {Floats::load(s0), Floats::load(s1), Floats::load(s2), Floats::load(s3)};
    }
    Vec3Of<Floats> frame() const { return {Floats::load(xx), Floats::load(xy), Floats::load(xz)}; }
    void store(const StokesOf<Floats>& st, const Vec3Of<Floats>& x) {
        st.s0.store(s0), st.s1.store(s1), st.s2.store(s2), st.s3.store(s3);
        x.x.store(xx), x.y.store(xy), x.z.store(xz);
    }
};

// Photons inside the stone, one per lane, as a structure of arrays.
struct alignas(64) Packet {
    float px[kMaxLanes]{}, py[kMaxLanes]{}, pz[kMaxLanes]{};
    float dx[kMaxLanes]{}, dy[kMaxLanes]{}, dz[kMaxLanes]{};
    float n[kMaxLanes]{};
    float absorption[kMaxLanes]{}, depth[kMaxLanes]{};  // PhotonWalker::Photon's, when the stone absorbs
    PolarizationLanes pol{};  // when the trace is polarised
    uint64_t rng[kMaxLanes]{};
    uint32_t bounces[kMaxLanes]{};
    uint32_t id[kMaxLanes]{};  // what the visitor knows the lane's photon by (Visitor::lane)
    LaneBits live = 0;

    void put(int k, const Vec3f& p, const Vec3f& d, float index, float alpha, float depthLeft,
             const Polarization& state, uint64_t rngState, uint32_t photonId) {
        px[k] = p.x, py[k] = p.y, pz[k] = p.z;
        dx[k] = d.x, dy[k] = d.y, dz[k] = d.z;
        n[k] = index;
        absorption[k] = alpha, depth[k] = depthLeft;
        pol.put(k, state);
        rng[k] = rngState;
        bounces[k] = 0;
        id[k] = photonId;
        live |= LaneBits(1) << k;
    }
    void put(int k, const PhotonWalker::Photon& ph, uint32_t photonId) {
        put(k, ph.p, ph.d, ph.n, ph.absorption, ph.depth, ph.pol, ph.rng.state(), photonId);
    }
    // Lane k takes the photon in lane j of another packet.
    void take(int k, const Packet& from, int j) {
        put(k, {from.px[j], from.py[j], from.pz[j]}, {from.dx[j], from.dy[j], from.dz[j]}, from.n[j],
            from.absorption[j], from.depth[j], from.pol[j], from.rng[j], from.id[j]);
    }
};

// What one step found, per lane, for the tallies that follow it.
struct alignas(64) StepResult {
    float px[kMaxLanes], py[kMaxLanes], pz[kMaxLanes];
    float cosI[kMaxLanes], cosT[kMaxLanes];
    int32_t facet[kMaxLanes];

    void store(Floats x, Floats y, Floats z, Floats cosIncidence, Floats cosRefracted, Facets f) {
        x.store(px), y.store(py), z.store(pz);
        cosIncidence.store(cosI), cosRefracted.store(cosT);
        hn::StoreU(f, IndexTag(), facet);
    }
    Vec3f p(int k) const { return {px[k], py[k], pz[k]}; }
};

// std::clamp(v, 0, 1) lane-wise, NaN kept as it is.
HWY_INLINE Floats clampUnit(Floats v) {
    const Floats zero(0.0f), one(1.0f);
    return select(v < zero, zero, select(one < v, one, v));
}

// The normal of each lane's facet.
struct Normals {
    Floats x, y, z;
};
HWY_INLINE Normals gatherNormals(const std::vector<Vec3f>& normal, Facets facet) {
    const IndexTag di;
    const float* x = &normal[0].x;
    const Facets at = hn::Mul(facet, hn::Set(di, 3));  // 3 floats per normal
    return {hn::GatherIndex(FloatTag(), x, at), hn::GatherIndex(FloatTag(), x + 1, at),
            hn::GatherIndex(FloatTag(), x + 2, at)};
}

// LightModel::sample() for a collimated beam, lane-wise: the disc point drawn by rejection in each lane's
// stream, the origin worked out in double and rounded to float as Vec3f does.
HWY_INLINE void sampleBeam(const LightModel::Disc& disc, uint64_t* state, Floats& ox, Floats& oy,
                           Floats& oz) {
    const HalfTag dh;
    const size_t half = hn::Lanes(StreamTag());
    const Doubles one(1.0), two(2.0), zero(0.0), radius(disc.radius);
    hn::Vec<HalfTag> origin[3][2];
    for (size_t h = 0; h < 2; ++h) {
        // unitDisc() lane-wise: each lane draws pairs until its own point falls inside the disc.
        Streams s = Streams::load(state + h * half);
        Doubles x = zero, y = zero;
        for (auto pending = hn::FirstN(StreamTag(), half); !hn::AllFalse(StreamTag(), pending);) {
            const Doubles cx = two * uniformDoubleOf(s, pending) - one;
            const Doubles cy = two * uniformDoubleOf(s, pending) - one;
            const Doubles r2 = cx * cx + cy * cy;
            const auto inside = hn::RebindMask(
                StreamTag(), hn::And(hn::RebindMask(DoubleTag(), pending), hn::And(r2 < one, zero < r2)));
            x = select(hn::RebindMask(DoubleTag(), inside), cx, x);
            y = select(hn::RebindMask(DoubleTag(), inside), cy, y);
            pending = hn::AndNot(inside, pending);
        }
        s.store(state + h * half);
        const Doubles sx = radius * x, sy = radius * y;
        auto component = [&](double c, double u, double v) HWY_ATTR {
            return hn::DemoteTo(dh, (Doubles(c) + Doubles(u) * sx + Doubles(v) * sy).v);
        };
        origin[0][h] = component(disc.center.x, disc.u.x, disc.v.x);
        origin[1][h] = component(disc.center.y, disc.u.y, disc.v.y);
        origin[2][h] = component(disc.center.z, disc.u.z, disc.v.z);
    }
    ox = hn::Combine(FloatTag(), origin[0][1], origin[0][0]);
    oy = hn::Combine(FloatTag(), origin[1][1], origin[1][0]);
    oz = hn::Combine(FloatTag(), origin[2][1], origin[2][0]);
}

using Packets = PhotonWalker::PacketScene;
using Tally = PhotonWalker::Tally;
using BandExit = PhotonWalker::BandExit;

// The photons of a packet where they meet the stone: PhotonWalker::start() for one collimated beam,
// lane-wise, up to the reflect-or-refract draw at entry.
struct BeamStart {
    StepResult hit;    // the entry point, facet and cos(incidence) (cosT: not known before the index)
    alignas(64) float wavelength[kMaxLanes];  // nm
    LaneBits photons = 0;  // the lanes that hold a photon
    LaneBits hits = 0;     // those that enter
};
// Photons [first, first + count) of the beam, their streams into state[], which advance by the draws of
// the light ray and of the wavelength when dispersive; with `n`, the index of refraction at each lane's
// wavelength into *n.
HWY_INLINE void startBeam(const Packets& s, uint64_t first, size_t count, uint64_t* state, BeamStart& b,
                          Floats* n) {
    const FloatMask lanes = hn::FirstN(FloatTag(), count);
    seedOf(s.seed, first, state);
    Floats ox, oy, oz;
    sampleBeam(s.light.disc(), state, ox, oy, oz);
    if (n) *n = Floats(s.fixedIndex);
    Floats wavelength(float(Material::kSodiumD));
    if (s.dispersive) {
        wavelength = Floats(380.0f) + Floats(400.0f) * uniformOf(state, lanes);
        if (n) *n = viaDoubles(wavelength, [&](Doubles w) HWY_ATTR { return s.material.indexOf(w); });
    }
    wavelength.store(b.wavelength);
    Floats t;
    Facets facet;
    const FloatMask hits = hn::And(lanes, EnterBeamPacket(*s.beam, ox, oy, oz, t, facet));
    b.photons = bitsOf(lanes);
    b.hits = bitsOf(hits);
    const Vec3f d(s.light.direction());
    const Floats dx(d.x), dy(d.y), dz(d.z);
    const Normals normal = gatherNormals(s.normal, facet);
    const Floats cosI = clampUnit(-dot3(dx, dy, dz, normal.x, normal.y, normal.z));
    b.hit.store(ox + dx * t, oy + dy * t, oz + dz * t, cosI, cosI, facet);
}

// The rest of start() for the photons of `b` at index n, absorbing absorption[k] per mesh unit in lane k,
// drawing from state[]: the photons that reflect off the stone, and those that get in as live lanes of
// `started` (which has none live before), the photon in lane k known to the visitor as firstId + k * idStep.
template <class Visitor>
HWY_INLINE void enterBeam(const Packets& s, const BeamStart& b, Floats n, const float* absorption,
                          uint64_t* state, Visitor& visit, uint32_t firstId, uint32_t idStep,
                          Packet& started) {
    const Vec3f d(s.light.direction());
    const Floats eta = Floats(1.0f) / n, cosI = Floats::load(b.hit.cosI);
    // The reflect-or-refract draw by the unpolarised Fresnel reflectance, or (PhotonWalker::enterPolarized)
    // by the share of the light's state that the reflected wave takes: the state inside into `inside`.
    FresnelTerms<Floats> fr;
    PolarizationLanes inside;
    if (s.polarized) {
        const Polarization source = s.trace.sourcePolarization(d);
        const Stokes& st = source.stokes;
        const Normals normal = gatherNormals(s.normal, hn::LoadU(IndexTag(), b.hit.facet));
        const FacetMeeting<Floats> m = meetFacet(
            StokesOf<Floats>{Floats(st.s0), Floats(st.s1), Floats(st.s2), Floats(st.s3)},
            Vec3Of<Floats>{Floats(source.x.x), Floats(source.x.y), Floats(source.x.z)},
            Vec3Of<Floats>{Floats(d.x), Floats(d.y), Floats(d.z)}, {normal.x, normal.y, normal.z}, cosI, eta);
        fr = {m.waves.totalInternal, m.waves.reflected.share(m.stokes), m.waves.cosT};
        inside.store(m.waves.refracted.apply(m.stokes), m.s);
    } else {
        fr = fresnelTerms(cosI, eta);
    }
    const LaneBits hitBits = b.hits;
    const FloatMask hits = maskOf(hitBits);
    const LaneBits reflects = bitsOf(hn::And(hits, uniformOf(state, hits) < fr.reflectance));
    alignas(64) float index[kMaxLanes], etas[kMaxLanes], cosT[kMaxLanes];
    n.store(index), eta.store(etas), fr.cosT.store(cosT);
    forEachLane(b.photons & ~hitBits, [&](int k) { visit.lane(firstId + k * idStep).missed(); });
    forEachLane(reflects, [&](int k) {
        const uint32_t f = b.hit.facet[k];
        visit.lane(firstId + k * idStep)
            .reflectedAtEntry(f, b.hit.p(k), reflectOff(d, s.normal[f], b.hit.cosI[k]));
    });
    forEachLane(hitBits & ~reflects, [&](int k) {
        const uint32_t f = b.hit.facet[k];
        visit.lane(firstId + k * idStep).entered(f);
        // PhotonWalker::enter()'s free path, from the lane's own stream.
        float depth = 0;
        if (absorption[k] > 0) {
            Rng rng = Rng::resume(state[k]);
            depth = PhotonWalker::freePath(rng);
            state[k] = rng.state();
        }
        started.put(k, b.hit.p(k), refractIn(d, s.normal[f], etas[k], b.hit.cosI[k], cosT[k]), index[k],
                    absorption[k], depth, s.polarized ? inside[k] : Polarization{}, state[k],
                    firstId + k * idStep);
    });
}

// enterBeam() by the facets' entries at index n (TraceBase::FixedEntry: every photon of a collimated beam
// meets a facet alike, and the entry holds what enterBeam() would work out for it, by the same operations),
// each photon absorbing `absorption` per mesh unit.
template <class Visitor>
HWY_INLINE void enterBeamFixed(const BeamStart& b, const std::vector<TraceBase::FixedEntry>& entries, float n,
                               float absorption, uint64_t* state, Visitor& visit, uint32_t firstId,
                               uint32_t idStep, Packet& started) {
    const LaneBits hitBits = b.hits;
    alignas(64) float reflectance[kMaxLanes] = {};
    forEachLane(hitBits, [&](int k) { reflectance[k] = entries[b.hit.facet[k]].reflectance; });
    const FloatMask hits = maskOf(hitBits);
    const LaneBits reflects = bitsOf(hn::And(hits, uniformOf(state, hits) < Floats::load(reflectance)));
    forEachLane(b.photons & ~hitBits, [&](int k) { visit.lane(firstId + k * idStep).missed(); });
    forEachLane(reflects, [&](int k) {
        const uint32_t f = b.hit.facet[k];
        visit.lane(firstId + k * idStep).reflectedAtEntry(f, b.hit.p(k), entries[f].reflected);
    });
    forEachLane(hitBits & ~reflects, [&](int k) {
        const uint32_t f = b.hit.facet[k];
        visit.lane(firstId + k * idStep).entered(f);
        float depth = 0;
        if (absorption > 0) {
            Rng rng = Rng::resume(state[k]);
            depth = PhotonWalker::freePath(rng);
            state[k] = rng.state();
        }
        started.put(k, b.hit.p(k), entries[f].refracted, n, absorption, depth, entries[f].inside, state[k],
                    firstId + k * idStep);
    });
}

// A packet of photons of one collimated beam up to their entry (startBeam()), kept for the fire trace's
// bands: their streams after the light ray and the wavelength, and where they meet the stone.
struct KeptStart {
    BeamStart beam;
    alignas(64) uint64_t drawn[kMaxLanes];
};

// PhotonWalker::start() for photons [first, min(first + lanes, end)) of the block from `begin`: visits
// those that miss or reflect off the stone and makes those that get in live lanes of `started`, which has
// none live before. With `keep`, a collimated beam's start goes there too.
template <class Visitor>
void startPacket(const Packets& s, uint64_t begin, uint64_t first, uint64_t end, Visitor& visit,
                 Packet& started, KeptStart* keep) {
    const size_t count = std::min<uint64_t>(laneCount(), end - first);
    if (!s.beam) {
        int k = 0;
        for (uint64_t i = first; i < first + count; ++i) {
            PhotonWalker::Photon ph;
            if (PhotonWalker::start(s.trace, s.convex, i, visit.lane(uint32_t(i - begin)), ph))
                started.put(k++, ph, uint32_t(i - begin));
        }
        return;
    }
    BeamStart b;
    Floats n;
    startBeam(s, first, count, started.rng, b, &n);
    if (keep) {
        keep->beam = b;
        std::copy_n(started.rng, kMaxLanes, keep->drawn);
    }
    alignas(64) float absorption[kMaxLanes] = {};
    if (s.trace.absorbs())
        forEachLane(b.hits, [&](int k) { absorption[k] = s.trace.absorption(b.wavelength[k]); });
    enterBeam(s, b, n, absorption, started.rng, visit, uint32_t(first - begin), 1, started);
}

// PhotonWalker::step() for every live lane of the packet, in a polarised trace or not, through an absorbing
// stone or not; the lanes whose photon is done are no longer live.
template <bool kPolarized, bool kAbsorbing, class Visitor>
void stepPacket(const Packets& s, Packet& lanes, Visitor& visit) {
    static_assert(
        !requires(Visitor & v, const Polarization& pol, const Vec3f& d) {
            v.lane(0).exitPolarization(pol, d);
        },
        "the packet walk does not work out the state a photon leaves in");
    const Floats ox = Floats::load(lanes.px), oy = Floats::load(lanes.py), oz = Floats::load(lanes.pz);
    const Floats dx = Floats::load(lanes.dx), dy = Floats::load(lanes.dy), dz = Floats::load(lanes.dz);
    Floats t;
    Facets facet;
    const FloatMask walking = maskOf(lanes.live);
    LeavePacket(s.convex, walking, ox, oy, oz, dx, dy, dz, t, facet);
    const FloatMask inside = hn::And(walking, t < Floats(kInf));
    // The photons that reach the facet: those whose free path outlasts the segment (PhotonWalker::step()).
    FloatMask meets = inside;
    LaneBits absorbed = 0;
    if constexpr (kAbsorbing) {
        const Floats depth = depthLeft(Floats::load(lanes.depth), Floats::load(lanes.absorption), t);
        depth.store(lanes.depth);
        const FloatMask gone = hn::And(inside, depth < Floats(0.0f));
        absorbed = bitsOf(gone);
        meets = hn::AndNot(gone, inside);
    }
    const Floats px = ox + dx * t, py = oy + dy * t, pz = oz + dz * t;
    const Normals normal = gatherNormals(s.normal, facet);
    const Floats cosI = clampUnit(dot3(dx, dy, dz, normal.x, normal.y, normal.z));
    // The reflect-or-refract choice: by the unpolarised Fresnel reflectance, or by the share of the photon's
    // own state that the reflected wave takes; a photon that reflects goes on in the facet's s-p frame.
    FresnelTerms<Floats> fr;
    if constexpr (kPolarized) {
        const FacetMeeting<Floats> m = meetFacet(lanes.pol.stokes(), lanes.pol.frame(), {dx, dy, dz},
                                                 {normal.x, normal.y, normal.z}, cosI, Floats::load(lanes.n));
        fr = {m.waves.totalInternal, m.waves.reflected.share(m.stokes), m.waves.cosT};
        lanes.pol.store(m.waves.reflected.apply(m.stokes), m.s);
    } else {
        fr = fresnelTerms(cosI, Floats::load(lanes.n));
    }
    const FloatMask draw = hn::AndNot(fr.totalInternal, meets);
    const LaneBits exits = bitsOf(hn::And(draw, uniformOf(lanes.rng, draw) >= fr.reflectance));
    const LaneBits live = lanes.live, reflects = bitsOf(meets) & ~exits;

    StepResult hit;
    hit.store(px, py, pz, cosI, fr.cosT, facet);
    forEachLane(live & ~bitsOf(inside), [&](int k) { visit.lane(lanes.id[k]).lost(lanes.bounces[k]); });
    forEachLane(absorbed, [&](int k) { visit.lane(lanes.id[k]).absorbed(lanes.bounces[k]); });
    forEachLane(exits, [&](int k) {
        const uint32_t f = hit.facet[k];
        const Vec3f d{lanes.dx[k], lanes.dy[k], lanes.dz[k]};
        visit.lane(lanes.id[k])
            .exited(f, hit.p(k), refractOut(d, s.normal[f], lanes.n[k], hit.cosI[k], hit.cosT[k]),
                    lanes.bounces[k]);
    });

    // The reflected photons go on from the hit point; each counts a bounce.
    const Floats twoCos = Floats(2.0f) * cosI;
    (dx - normal.x * twoCos).store(lanes.dx), (dy - normal.y * twoCos).store(lanes.dy);
    (dz - normal.z * twoCos).store(lanes.dz);
    px.store(lanes.px), py.store(lanes.py), pz.store(lanes.pz);
    LaneBits trapped = 0;
    forEachLane(reflects, [&](int k) {
        auto& v = visit.lane(lanes.id[k]);
        v.internalReflection(hit.facet[k]);
        if (++lanes.bounces[k] < s.maxBounces) return;
        v.trapped(lanes.bounces[k]);
        trapped |= LaneBits(1) << k;
    });
    lanes.live = reflects & ~trapped;
}

// A birefringent stone's photons, one per lane: the exit search a packet at a time, a uniaxial stone's
// crystal interfaces in lanes of doubles, the rest of each step (PhotonWalker::meet()) lane by lane, each
// lane's photon kept whole. A collimated beam's photons are started as a packet up to their entry search
// (startBeam()), then enter lane by lane (PhotonWalker::enterAt()); other light's one photon at a time.
struct alignas(64) CrystalPacket {
    float px[kMaxLanes]{}, py[kMaxLanes]{}, pz[kMaxLanes]{};  // the photons' p and d, for the exit search
    float dx[kMaxLanes]{}, dy[kMaxLanes]{}, dz[kMaxLanes]{};
    PhotonWalker::Photon ph[kMaxLanes];
    uint32_t id[kMaxLanes]{};
    LaneBits live = 0;

    void put(int k, const PhotonWalker::Photon& photon, uint32_t photonId) {
        ph[k] = photon;
        px[k] = photon.p.x, py[k] = photon.p.y, pz[k] = photon.p.z;
        dx[k] = photon.d.x, dy[k] = photon.d.y, dz[k] = photon.d.z;
        id[k] = photonId;
        live |= LaneBits(1) << k;
    }
};

// PhotonWalker::start() for photons [first, min(first + lanes, end)) of the block from `begin`, as
// startPacket() does: those that get in become live lanes of `started`, which has none live before.
template <class Visitor>
void startCrystalPacket(const Packets& s, uint64_t begin, uint64_t first, uint64_t end, Visitor& visit,
                        CrystalPacket& started) {
    const size_t count = std::min<uint64_t>(laneCount(), end - first);
    int next = 0;  // started's next lane
    if (!s.beam) {
        for (uint64_t i = first; i < first + count; ++i) {
            PhotonWalker::Photon ph;
            const uint32_t id = uint32_t(i - begin);
            if (PhotonWalker::start(s.trace, s.convex, i, visit.lane(id), ph)) started.put(next++, ph, id);
        }
        return;
    }
    BeamStart b;
    Floats n;
    alignas(64) uint64_t state[kMaxLanes];
    startBeam(s, first, count, state, b, &n);
    alignas(64) float index[kMaxLanes];
    n.store(index);
    const Vec3f d(s.light.direction());
    // A uniaxial stone's entries, lanes of doubles at a time (optics/uniaxial_interface-inl.h), for the lanes
    // that meet it: lane k's waves are uniaxial::EntryLane{entries + slot[k], kMaxLanes} where bit k of
    // `entered` is set; enterAt() finds the others' (uniaxial::UniaxialEntry's conditions unmet) one at a
    // time.
    alignas(64) float extraordinary[kMaxLanes];
    alignas(64) double entries[uniaxial::UniaxialEntry<double>::kNumbers * kMaxLanes];
    int slot[kMaxLanes];
    LaneBits entered = 0;
    uint64_t reflects = 0, ordinary = 0;
    constexpr bool kEntryDraws = HWY_TARGET != HWY_SSE4;
    const bool laneEntries = s.trace.polarized() && !s.trace.biaxial() && s.trace.fixedEntries().empty();
    if (laneEntries) {
        // Each lane's n_e as TraceBase::principalIndex() gives it: at the lane's wavelength when dispersive.
        (s.dispersive ? viaDoubles(Floats::load(b.wavelength),
                                   [&](Doubles w) HWY_ATTR { return s.material.principalIndexOf(2, w); })
                      : Floats(s.trace.principalIndex(2, Material::kSodiumD)))
            .store(extraordinary);
        alignas(64) double nO[kMaxLanes], nE[kMaxLanes], dir[3][kMaxLanes], normal[3][kMaxLanes];
        alignas(64) uint64_t stream[kMaxLanes];
        int lane[kMaxLanes], count = 0;
        forEachLane(b.photons & b.hits, [&](int k) {
            const Vec3f& nk = s.trace.scene().normal(uint32_t(b.hit.facet[k]));
            nO[count] = index[k], nE[count] = extraordinary[k];
            dir[0][count] = d.x, dir[1][count] = d.y, dir[2][count] = d.z;
            normal[0][count] = nk.x, normal[1][count] = nk.y, normal[2][count] = nk.z;
            stream[count] = state[k];
            slot[k] = count, lane[count++] = k;
        });
        const double* const dirs[3] = {dir[0], dir[1], dir[2]};
        const double* const normals[3] = {normal[0], normal[1], normal[2]};
        const uint64_t met = enterUniaxialLanes(s.trace.opticAxis(), 1, nO, nE, dirs, normals, size_t(count),
                                                entries, kMaxLanes);
        forEachLane(met, [&](int j) { entered |= LaneBits(1) << lane[j]; });
        // Their draws too (enterAt() draws nothing before its choice), but on SSE4: with two lanes of doubles
        // they cost more than they save there (docs/performance.md, issue 28, 2026-12-03 20:04).
        if (kEntryDraws && met)
            drawEntryLanes(s.trace.sourcePolarization(d), d, entries, kMaxLanes, stream, size_t(count),
                           reflects, ordinary);
    }
    forEachLane(b.photons, [&](int k) {
        const uint32_t id = uint32_t(first - begin) + uint32_t(k);
        auto& v = visit.lane(id);
        v.wavelength(b.wavelength[k]);
        if (!(b.hits >> k & 1)) {
            v.missed();
            return;
        }
        PhotonWalker::Photon ph;
        ph.rng = Rng::resume(state[k]);
        ph.n = index[k];
        ph.nE = laneEntries ? extraordinary[k] : s.trace.principalIndex(2, b.wavelength[k]);
        if (s.trace.biaxial()) ph.nA = s.trace.principalIndex(0, b.wavelength[k]);
        ph.setAbsorption(s.trace, b.wavelength[k]);
        const int j = entered >> k & 1 ? slot[k] : 0;
        const uniaxial::EntryLane entry{entries + j, kMaxLanes,
                                        !kEntryDraws        ? uniaxial::EntryLane::kNotDrawn
                                        : reflects >> j & 1 ? -1
                                                            : int(~ordinary >> j & 1)};
        if (PhotonWalker::enterAt(s.trace, uint32_t(b.hit.facet[k]), b.hit.p(k), d, v, ph,
                                  entered >> k & 1 ? &entry : nullptr))
            started.put(next++, ph, id);
    });
}

// PhotonWalker::step() for every live lane; the lanes whose photon is done are no longer live.
template <class Visitor>
void stepCrystalPacket(const Packets& s, CrystalPacket& lanes, Visitor& visit) {
    Floats t;
    Facets facet;
    LeavePacket(s.convex, maskOf(lanes.live), Floats::load(lanes.px), Floats::load(lanes.py),
                Floats::load(lanes.pz), Floats::load(lanes.dx), Floats::load(lanes.dy),
                Floats::load(lanes.dz), t, facet);
    alignas(64) float ts[kMaxLanes];
    alignas(64) int32_t facets[kMaxLanes];
    t.store(ts);
    hn::StoreU(facet, IndexTag(), facets);
    // A uniaxial stone's leavings, lanes of doubles at a time (optics/uniaxial_interface-inl.h), for the
    // lanes whose photon goes on as one crystal wave: lane k's waves are uniaxial::LeavingLane{leavings +
    // slot[k], kMaxLanes, ...} where bit k of `left` is set; meet() finds the others' one at a time.
    alignas(64) double leavings[uniaxial::UniaxialLeaving<double>::kNumbers * kMaxLanes];
    int slot[kMaxLanes];
    uint64_t evanescent = 0, out = 0, ordinary = 0;
    LaneBits left = 0;
    if (!s.trace.biaxial()) {
        alignas(64) double nO[kMaxLanes], nE[kMaxLanes], normal[3][kMaxLanes];
        alignas(64) uint64_t state[kMaxLanes];
        const PlaneWave* incident[kMaxLanes];
        int lane[kMaxLanes], count = 0;
        forEachLane(lanes.live, [&](int k) {
            const PhotonWalker::Photon& ph = lanes.ph[k];
            if (!(ts[k] < kInf) || ph.coherent) return;
            const Vec3f& nk = s.trace.scene().normal(uint32_t(facets[k]));
            nO[count] = ph.n, nE[count] = ph.nE;
            normal[0][count] = nk.x, normal[1][count] = nk.y, normal[2][count] = nk.z;
            incident[count] = &ph.wave;
            state[count] = ph.rng.state();
            slot[k] = count, lane[count++] = k;
        });
        const double* const normals[3] = {normal[0], normal[1], normal[2]};
        const uint64_t met = leaveUniaxialLanes(s.trace.opticAxis(), 1, nO, nE, incident, normals,
                                                size_t(count), leavings, kMaxLanes, evanescent);
        forEachLane(met, [&](int j) { left |= LaneBits(1) << lane[j]; });
        // Their draws too (the photon's next number: meet() draws nothing before its choice).
        if (met) drawLeavingLanes(leavings, kMaxLanes, state, size_t(count), out, ordinary);
    }
    forEachLane(lanes.live, [&](int k) {
        PhotonWalker::Photon& ph = lanes.ph[k];
        auto& v = visit.lane(lanes.id[k]);
        bool stays = false;
        if (!(ts[k] < kInf)) {
            v.lost(ph.bounces);
        } else if (left >> k & 1) {
            const int j = slot[k];
            const uniaxial::LeavingLane leaving{leavings + j, kMaxLanes, bool(evanescent >> j & 1),
                                                out >> j & 1 ? -1 : int(~ordinary >> j & 1)};
            stays = PhotonWalker::meet(s.trace, SurfaceHit{ts[k], uint32_t(facets[k])}, v, ph, &leaving);
        } else {
            stays = PhotonWalker::meet(s.trace, SurfaceHit{ts[k], uint32_t(facets[k])}, v, ph);
        }
        if (!stays) {
            lanes.live &= ~(LaneBits(1) << k);
            return;
        }
        lanes.px[k] = ph.p.x, lanes.py[k] = ph.p.y, lanes.pz[k] = ph.p.z;
        lanes.dx[k] = ph.d.x, lanes.dy[k] = ph.d.y, lanes.dz[k] = ph.d.z;
    });
}

// Photons [begin, end) of a birefringent convex stone, a packet at a time, as walkLanes() steps them, photon
// i known to the visitor as i - begin.
template <class Visitor>
void walkCrystalPhotons(const Packets& s, uint64_t begin, uint64_t end, Visitor& visit) {
    const LaneBits all = laneCount() == 64 ? ~LaneBits(0) : (LaneBits(1) << laneCount()) - 1;
    CrystalPacket lanes, started;  // started: photons inside the stone, waiting for a lane
    uint64_t next = begin;         // the first photon not started
    for (;;) {
        for (LaneBits empty = all & ~lanes.live; empty;) {
            if (!started.live) {
                if (next >= end) break;
                startCrystalPacket(s, begin, next, end, visit, started);
                next += laneCount();
                continue;
            }
            const int j = std::countr_zero(started.live);
            lanes.put(std::countr_zero(empty), started.ph[j], started.id[j]);
            started.live &= started.live - 1;
            empty &= empty - 1;
        }
        if (!lanes.live) return;
        stepCrystalPacket(s, lanes, visit);
    }
}

// Steps lanes until start(started) has no more photons to put into `started` (which has none live when it is
// called) and every lane is done. A lane whose photon is done takes the next started photon.
template <class Visitor, class Start>
void walkLanes(const Packets& s, Visitor& visit, Start&& start) {
    const LaneBits all = laneCount() == 64 ? ~LaneBits(0) : (LaneBits(1) << laneCount()) - 1;
    Packet lanes, started;  // started: photons inside the stone, waiting for a lane
    for (bool more = true;;) {
        for (LaneBits empty = all & ~lanes.live; empty;) {
            if (!started.live) {
                if (!more || !(more = start(started))) break;
                continue;
            }
            lanes.take(std::countr_zero(empty), started, std::countr_zero(started.live));
            started.live &= started.live - 1;
            empty &= empty - 1;
        }
        if (!lanes.live) return;
        if (s.polarized) {
            s.trace.absorbs() ? stepPacket<true, true>(s, lanes, visit)
                              : stepPacket<true, false>(s, lanes, visit);
        } else {
            s.trace.absorbs() ? stepPacket<false, true>(s, lanes, visit)
                              : stepPacket<false, false>(s, lanes, visit);
        }
    }
}

// The visitor of a band walk's lanes: lane id is exits[id].
struct BandExits {
    std::span<BandExit> exits;
    BandExit& lane(uint32_t id) { return exits[id]; }
};

// Photons [begin, end) of a convex stone, a packet at a time, photon i known to the visitor as i - begin;
// with `keep`, a collimated beam's packets' starts into keep[0], keep[1], ... in turn.
template <class Visitor>
void walkPhotons(const Packets& s, uint64_t begin, uint64_t end, Visitor& visit, KeptStart* keep) {
    uint64_t next = begin;
    walkLanes(s, visit, [&](Packet& started) {
        if (next >= end) return false;
        startPacket(s, begin, next, end, visit, started, keep);
        if (keep) ++keep;
        next += laneCount();
        return true;
    });
}

// The bands of photons [begin, end), one (photon, band) per lane (walkBandPackets()); with `kept`, a
// collimated beam's packets start as kept[0], kept[1], ... in turn.
void walkBands(const Packets& s, uint64_t begin, uint64_t end, std::span<const FireBand> bands,
               std::span<PhotonWalker::BandExit> exits, const KeptStart* kept);

}  // namespace

// Photons [begin, end) of a convex stone, a packet at a time. Each photon takes exactly the steps walk()
// takes, so the tally has the same bits.
void walkPackets(const PhotonWalker::PacketScene& s, uint64_t begin, uint64_t end,
                 PhotonWalker::Tally& tally) {
    if (s.trace.birefringent()) {
        walkCrystalPhotons(s, begin, end, tally);
        return;
    }
    walkPhotons(s, begin, end, tally, nullptr);
}

// walkPackets() with each photon's walk also recorded (PhotonWalker::TallyWithExits).
void walkPacketsWithExits(const PhotonWalker::PacketScene& s, uint64_t begin, uint64_t end,
                          PhotonWalker::TallyWithExits& visit) {
    walkPhotons(s, begin, end, visit, nullptr);
}

// The bands of photons [begin, end), one (photon, band) per lane: a packet of photons is started once (the
// light ray and the entry do not depend on the index of refraction) and enters at each band's index in turn,
// each band from its own copy of the photon's stream. Each band takes exactly the steps walkBands() takes.
void walkBandPackets(const PhotonWalker::PacketScene& s, uint64_t begin, uint64_t end,
                     std::span<const FireBand> bands, std::span<PhotonWalker::BandExit> exits) {
    walkBands(s, begin, end, bands, exits, nullptr);
}

// Photons [begin, end) into the tally, and their bands into `exits` (walkPackets() and walkBandPackets()):
// a collimated beam's photons are started once for both, since the light ray, the wavelength draw and
// the entry search do not depend on the index of refraction.
void walkPacketsAndBands(const PhotonWalker::PacketScene& s, uint64_t begin, uint64_t end,
                         PhotonWalker::Tally& tally, std::span<const FireBand> bands,
                         std::span<PhotonWalker::BandExit> exits) {
    thread_local std::vector<KeptStart> kept;  // the block's, sized once per thread
    KeptStart* keep = nullptr;
    if (s.beam) {
        kept.resize((end - begin + laneCount() - 1) / laneCount());
        keep = kept.data();
    }
    walkPhotons(s, begin, end, tally, keep);
    walkBands(s, begin, end, bands, exits, keep);
}

namespace {
void walkBands(const Packets& s, uint64_t begin, uint64_t end, std::span<const FireBand> bands,
               std::span<PhotonWalker::BandExit> exits, const KeptStart* kept) {
    BandExits visit{exits};
    const uint32_t count = uint32_t(bands.size());
    uint64_t first = begin;  // the packet of photons being started
    size_t band = count;     // the band it enters at next
    BeamStart beam;
    alignas(64) uint64_t drawn[kMaxLanes];  // the photons' streams after the light ray and the wavelength
    uint64_t next = begin;                  // the first photon not started
    // The bands enter by the trace's entries per facet where it has them for these bands.
    bool fixed = s.beam && bands.size() == kFireBands;
    for (size_t k = 0; fixed && k < bands.size(); ++k)
        fixed = !s.trace.bandEntries(int(k)).empty() && s.trace.bandEntryIndex(int(k)) == bands[k].index;
    walkLanes(s, visit, [&](Packet& started) {
        if (band == count) {  // every band of the packet has entered: the next packet of photons
            if (next >= end) return false;
            first = next;
            next = std::min<uint64_t>(first + laneCount(), end);
            band = 0;
            if (kept) {
                beam = kept->beam;
                std::copy_n(kept->drawn, kMaxLanes, drawn);
                ++kept;
            } else if (s.beam) {
                startBeam(s, first, next - first, drawn, beam, nullptr);
            }
        }
        const uint32_t firstId = uint32_t((first - begin) * count + band);
        if (fixed) {
            std::copy_n(drawn, laneCount(), started.rng);
            enterBeamFixed(beam, s.trace.bandEntries(int(band)), bands[band].index,
                           s.trace.absorption(bands[band].wavelengthNm), started.rng, visit, firstId, count,
                           started);
        } else if (s.beam) {
            std::copy_n(drawn, laneCount(), started.rng);
            alignas(64) float absorption[kMaxLanes];
            std::fill_n(absorption, kMaxLanes, s.trace.absorption(bands[band].wavelengthNm));
            enterBeam(s, beam, Floats(bands[band].index), absorption, started.rng, visit, firstId, count,
                      started);
        } else {
            int k = 0;
            for (uint64_t i = first; i < next; ++i) {
                const uint32_t id = firstId + uint32_t(i - first) * count;
                PhotonWalker::Photon ph;
                if (PhotonWalker::startBand(s.trace, s.convex, i, bands[band], visit.lane(id), ph))
                    started.put(k++, ph, id);
            }
        }
        ++band;
        return true;
    });
}
}  // namespace
#else
// Highway's one-lane fallback (x86 CPUs without SSE4): one photon at a time.
void walkPackets(const PhotonWalker::PacketScene& s, uint64_t begin, uint64_t end,
                 PhotonWalker::Tally& tally) {
    for (uint64_t i = begin; i < end; ++i) PhotonWalker::walk(s.trace, s.convex, i, tally);
}
void walkPacketsWithExits(const PhotonWalker::PacketScene& s, uint64_t begin, uint64_t end,
                          PhotonWalker::TallyWithExits& visit) {
    for (uint64_t i = begin; i < end; ++i)
        PhotonWalker::walk(s.trace, s.convex, i, visit.lane(uint32_t(i - begin)));
}
void walkBandPackets(const PhotonWalker::PacketScene& s, uint64_t begin, uint64_t end,
                     std::span<const FireBand> bands, std::span<PhotonWalker::BandExit> exits) {
    for (uint64_t i = begin; i < end; ++i)
        PhotonWalker::walkBands(s.trace, s.convex, i, bands,
                                exits.subspan((i - begin) * bands.size(), bands.size()));
}
void walkPacketsAndBands(const PhotonWalker::PacketScene& s, uint64_t begin, uint64_t end,
                         PhotonWalker::Tally& tally, std::span<const FireBand> bands,
                         std::span<PhotonWalker::BandExit> exits) {
    walkPackets(s, begin, end, tally);
    walkBandPackets(s, begin, end, bands, exits);
}
#endif

}  // namespace HWY_NAMESPACE
}  // namespace facetlight
HWY_AFTER_NAMESPACE();

#if HWY_ONCE
namespace facetlight {

HWY_EXPORT(walkPackets);
HWY_EXPORT(walkPacketsWithExits);
HWY_EXPORT(walkBandPackets);
HWY_EXPORT(walkPacketsAndBands);

PhotonWalker::PacketScene PhotonWalker::packetScene(const TraceBase& t) {
    const Scene& s = t.scene();
    return {t,
            *s.convex(),
            s.beamEntry(),
            s.light(),
            s.material(),
            s.normals(),
            s.fixedIndex(),
            s.dispersive(),
            t.polarized(),
            t.settings().seed,
            uint32_t(t.settings().maxBounces)};
}

void PhotonWalker::packets(const TraceBase& s, uint64_t begin, uint64_t end, Tally& tally) {
    HWY_DYNAMIC_DISPATCH(walkPackets)(packetScene(s), begin, end, tally);
}

void PhotonWalker::packetsWithExits(const TraceBase& s, uint64_t begin, uint64_t end, TallyWithExits& visit) {
    HWY_DYNAMIC_DISPATCH(walkPacketsWithExits)(packetScene(s), begin, end, visit);
}

void PhotonWalker::packetsAndBands(const TraceBase& s, uint64_t begin, uint64_t end, Tally& tally,
                                   std::span<const FireBand> bands, std::span<BandExit> exits) {
    HWY_DYNAMIC_DISPATCH(walkPacketsAndBands)(packetScene(s), begin, end, tally, bands, exits);
}

void PhotonWalker::bandPackets(const TraceBase& s, uint64_t begin, uint64_t end,
                               std::span<const FireBand> bands, std::span<BandExit> exits) {
    HWY_DYNAMIC_DISPATCH(walkBandPackets)(packetScene(s), begin, end, bands, exits);
}

}  // namespace facetlight
#endif
