// Inside core/ (per SIMD target, included after hwy/foreach_target.h or hwy/highway.h): Highway vectors
// with the operators of their scalar types, so that one template, such as fresnelTerms, Material::indexOf or
// mix64, computes the same bits for one photon and for a lane of a packet. Each operator is one correctly
// rounded operation (add, sub, mul, div, sqrt; no fused multiply-add, no approximate reciprocal) on every
// target, as the scalar operator is when the compiler does not contract a * b + c (core/ is built with
// -ffp-contract=off).
//
// The shared templates (fresnelTerms, Material::indexOf, mix64) are compiled without the target's options and
// always inlined into the per-target caller; the operators here are plain inline functions with the target's
// options, which the compiler then inlines into that caller (it may not inline them into the template
// itself).
#if defined(FACETLIGHT_LANES_INL_H_) == defined(HWY_TARGET_TOGGLE)
#ifdef FACETLIGHT_LANES_INL_H_
#undef FACETLIGHT_LANES_INL_H_
#else
#define FACETLIGHT_LANES_INL_H_
#endif

#include <cstdint>

#include "hwy/highway.h"
#include "util/random.h"

HWY_BEFORE_NAMESPACE();
namespace facetlight {
namespace HWY_NAMESPACE {
namespace hn = hwy::HWY_NAMESPACE;

// A vector of tag D's lanes with the operators of its scalar type.
template <class D>
struct Lanes {
    using T = hn::TFromD<D>;
    using V = hn::Vec<D>;
    V v;
    Lanes() = default;
    Lanes(V x) : v(x) {}
    explicit Lanes(T s) : v(hn::Set(D(), s)) {}
    static Lanes load(const T* p) { return hn::LoadU(D(), p); }
    void store(T* p) const { hn::StoreU(v, D(), p); }
};

template <class D>
inline Lanes<D> operator+(Lanes<D> a, Lanes<D> b) {
    return hn::Add(a.v, b.v);
}
template <class D>
inline Lanes<D> operator-(Lanes<D> a, Lanes<D> b) {
    return hn::Sub(a.v, b.v);
}
template <class D>
inline Lanes<D> operator*(Lanes<D> a, Lanes<D> b) {
    return hn::Mul(a.v, b.v);
}
template <class D>
inline Lanes<D> operator/(Lanes<D> a, Lanes<D> b) {
    return hn::Div(a.v, b.v);
}
template <class D>
inline Lanes<D> operator-(Lanes<D> a) {
    return hn::Neg(a.v);  // the sign flipped, as scalar negation does
}
// Ordered comparisons, false where either side is NaN, as for scalar floats.
template <class D>
inline hn::Mask<D> operator<(Lanes<D> a, Lanes<D> b) {
    return hn::Lt(a.v, b.v);
}
template <class D>
inline hn::Mask<D> operator>=(Lanes<D> a, Lanes<D> b) {
    return hn::Ge(a.v, b.v);
}
template <class D>
inline Lanes<D> sqrt(Lanes<D> a) {
    return hn::Sqrt(a.v);
}
// std::copysign: the magnitude of a with the sign bit of b.
template <class D>
inline Lanes<D> copysign(Lanes<D> a, Lanes<D> b) {
    return hn::CopySign(a.v, b.v);
}
// a where the mask is set, else b: the lane-wise `mask ? a : b`.
template <class D>
inline Lanes<D> select(hn::Mask<D> mask, Lanes<D> a, Lanes<D> b) {
    return hn::IfThenElse(mask, a.v, b.v);
}

// The packet walk's lanes. Highway's one-lane fallback (HWY_SCALAR, for x86 CPUs without SSE4) has none: it
// walks one photon at a time.
#if HWY_TARGET != HWY_SCALAR
using FloatTag = hn::ScalableTag<float>;                // one lane per photon of a packet
using IndexTag = hn::RebindToSigned<FloatTag>;          // a facet per lane
using HalfTag = hn::Half<FloatTag>;                     // half a packet's floats, to widen to doubles
using DoubleTag = hn::Repartition<double, FloatTag>;    // half a packet, as doubles
using StreamTag = hn::Repartition<uint64_t, FloatTag>;  // half a packet's random streams

// SplitMix64's operations on 64-bit lanes, for mix64.
inline Lanes<StreamTag> operator^(Lanes<StreamTag> a, Lanes<StreamTag> b) {
    return hn::Xor(a.v, b.v);
}
inline Lanes<StreamTag> operator>>(Lanes<StreamTag> a, int shift) {
    return hn::ShiftRightSame(a.v, shift);
}
// The low 64 bits of the product, from 32 x 32-bit products (Highway 1.0.3 has no 64-bit lane multiply).
inline Lanes<StreamTag> operator*(Lanes<StreamTag> a, Lanes<StreamTag> b) {
    const hn::Repartition<uint32_t, StreamTag> d32;
    const auto lo = hn::MulEven(hn::BitCast(d32, a.v), hn::BitCast(d32, b.v));
    const auto cross = hn::Add(hn::MulEven(hn::BitCast(d32, hn::ShiftRight<32>(a.v)), hn::BitCast(d32, b.v)),
                               hn::MulEven(hn::BitCast(d32, a.v), hn::BitCast(d32, hn::ShiftRight<32>(b.v))));
    return hn::Add(lo, hn::ShiftLeft<32>(cross));
}

using Floats = Lanes<FloatTag>;
using Doubles = Lanes<DoubleTag>;
using Streams = Lanes<StreamTag>;
using FloatMask = hn::Mask<FloatTag>;

// The lanes of a packet's float mask, split into the two halves its 64-bit lanes hold.
template <bool kUpper>
HWY_INLINE hn::Mask<StreamTag> halfOf(FloatMask m) {
    const hn::Repartition<int64_t, FloatTag> d64;
    const hn::Half<IndexTag> dh;
    const auto lanes = hn::BitCast(IndexTag(), hn::VecFromMask(FloatTag(), m));
    const auto wide = hn::PromoteTo(d64, kUpper ? hn::UpperHalf(dh, lanes) : hn::LowerHalf(dh, lanes));
    return hn::MaskFromVec(hn::BitCast(StreamTag(), wide));
}

// Rng's draws for lanes of streams held as their states (Rng::state()), each lane drawing what its Rng
// would. Only the lanes in `draw` advance; the others keep their state and get an unspecified number.

// Rng::next() for one vector of streams.
HWY_INLINE Streams nextOf(Streams& state, hn::Mask<StreamTag> draw) {
    state = hn::IfThenElse(draw, (state + Streams(Rng::kGamma)).v, state.v);
    return mix64(state);
}
// Rng::uniformDouble() for one vector of streams.
HWY_INLINE Doubles uniformDoubleOf(Streams& state, hn::Mask<StreamTag> draw) {
    const hn::Repartition<int64_t, FloatTag> d64;
    return Doubles(hn::ConvertTo(DoubleTag(), hn::BitCast(d64, (nextOf(state, draw) >> 11).v))) *
           Doubles(0x1p-53);
}
// Rng::uniform() for a packet of streams, state[0..Lanes(FloatTag)).
HWY_INLINE Floats uniformOf(uint64_t* state, FloatMask draw) {
    const size_t half = hn::Lanes(StreamTag());
    Streams lo = Streams::load(state), hi = Streams::load(state + half);
    const Streams bitsLo = nextOf(lo, halfOf<false>(draw)) >> 40,
                  bitsHi = nextOf(hi, halfOf<true>(draw)) >> 40;
    lo.store(state), hi.store(state + half);
    // Each lane holds 24 bits: its low 32-bit half, converted exactly.
    const hn::Repartition<uint32_t, FloatTag> d32;
    const auto bits = hn::ConcatEven(d32, hn::BitCast(d32, bitsHi.v), hn::BitCast(d32, bitsLo.v));
    return Floats(hn::ConvertTo(FloatTag(), hn::BitCast(IndexTag(), bits))) * Floats(0x1p-24f);
}
// Rng::uniform() of the streams at state[0 .. Lanes(DoubleTag)), in doubles (24 bits times 2^-24: exact in
// double as in float), the states left as they are.
HWY_INLINE Doubles nextUniformOf(const uint64_t* state) {
    const hn::Repartition<int64_t, DoubleTag> d64;
    Streams s = Streams::load(state);
    const Streams bits = nextOf(s, hn::FirstN(StreamTag(), hn::Lanes(StreamTag()))) >> 40;
    return Doubles(hn::ConvertTo(DoubleTag(), hn::BitCast(d64, bits.v))) * Doubles(0x1p-24);
}
// The states of Rng(seed, firstStream + k) for k = 0 .. Lanes(FloatTag) - 1, into state[].
HWY_INLINE void seedOf(uint64_t seed, uint64_t firstStream, uint64_t* state) {
    const size_t half = hn::Lanes(StreamTag());
    for (size_t h = 0; h < 2; ++h) {
        const Streams stream =
            Streams(hn::Iota(StreamTag(), firstStream + h * half)) + Streams(Rng::kStreamOffset);
        mix64(Streams(seed) ^ mix64(stream)).store(state + h * half);
    }
}

// A function of doubles applied to a packet of floats, in two halves: f(double(x)) rounded to float.
template <class F>
HWY_INLINE Floats viaDoubles(Floats x, F&& f) {
    const HalfTag dh;
    const Doubles lo = hn::PromoteTo(DoubleTag(), hn::LowerHalf(dh, x.v));
    const Doubles hi = hn::PromoteTo(DoubleTag(), hn::UpperHalf(dh, x.v));
    return hn::Combine(FloatTag(), hn::DemoteTo(dh, f(hi).v), hn::DemoteTo(dh, f(lo).v));
}
#endif  // HWY_TARGET != HWY_SCALAR

}  // namespace HWY_NAMESPACE
}  // namespace facetlight
HWY_AFTER_NAMESPACE();

#endif
