#include "cuts/fancy_cuts.h"

#include <algorithm>
#include <cmath>
#include <string>

#include "geometry/halfspace.h"
#include "util/error.h"
#include "util/number_text.h"

namespace facetlight {

namespace {

constexpr int kArcSamples = 1024;

void addArc(std::vector<Vec3>& out, const Vec3& centre, double radius, double fromDeg, double toDeg) {
    for (int i = 0; i <= kArcSamples; ++i) {
        const double t = radians(fromDeg + (toDeg - fromDeg) * i / kArcSamples);
        out.push_back(centre + Vec3{radius * std::cos(t), radius * std::sin(t), 0});
    }
}

// The arcs of a pointed end: circles tangent to the sides y = +-1/2 at x = x0, meeting at the tip x0 + reach.
void addPointedEnd(std::vector<Vec3>& out, double x0, double reach, bool towardPlusX) {
    const double rho = reach * reach + 0.25;  // sqrt(rho^2 - (rho - 1/2)^2) == reach
    const double tipAngle = degrees(std::asin(reach / rho));
    const double s = towardPlusX ? 1 : -1;
    // Upper arc centred below the stone, lower arc centred above it.
    const Vec3 upper{x0, -(rho - 0.5), 0}, lower{x0, rho - 0.5, 0};
    if (towardPlusX) {
        addArc(out, upper, rho, 90 - tipAngle, 90);
        addArc(out, lower, rho, -90, -90 + tipAngle);
    } else {
        addArc(out, upper, rho, 90, 90 + tipAngle);
        addArc(out, lower, rho, -90 - tipAngle, -90);
    }
    out.push_back({x0 + s * reach, 0, 0});
}

double support(const std::vector<Vec3>& outline, const Vec3& direction) {
    double best = -INFINITY;
    for (const Vec3& p : outline) best = std::max(best, dot(p, direction));
    return best;
}

std::string num(double v) {
    return formatNumber("%g", v);
}

}  // namespace

std::vector<Vec3> fancyOutline(const FancyBrilliantParams& p) {
    const double L = p.ratio, k = p.cornerPct / 100;
    if (!(L >= 1 && L <= 3)) throw Error("ratio " + num(L) + ": length / width must lie between 1 and 3");
    std::vector<Vec3> out;
    switch (p.outline) {
        case FancyOutline::Oval:
            for (int i = 0; i < 4 * kArcSamples; ++i) {
                const double t = 2 * kPi * i / (4 * kArcSamples);
                out.push_back({L / 2 * std::cos(t), 0.5 * std::sin(t), 0});
            }
            break;
        case FancyOutline::Marquise:
            if (L <= 1) throw Error("ratio " + num(L) + ": a marquise must be longer than wide");
            addPointedEnd(out, 0, L / 2, true);
            addPointedEnd(out, 0, L / 2, false);
            break;
        case FancyOutline::Pear:
            if (L <= 1) throw Error("ratio " + num(L) + ": a pear must be longer than wide");
            addArc(out, {0.5 - L / 2, 0, 0}, 0.5, 90, 270);
            addPointedEnd(out, 0.5 - L / 2, L - 0.5, true);
            break;
        case FancyOutline::Heart: {
            // Two lobes and a point; the hull bridges the cleft between the lobes.
            const double r = 0.28, back = -L / 2;
            addArc(out, {back + r, 0.5 - r, 0}, r, 0, 360);
            addArc(out, {back + r, -(0.5 - r), 0}, r, 0, 360);
            out.push_back({L / 2, 0, 0});
            break;
        }
        case FancyOutline::Cushion: {
            if (!(k > 0 && k <= 0.5))
                throw Error("corner " + num(p.cornerPct) + ": must lie in (0, 50]% of the width");
            for (double sx : {-1.0, 1.0})
                for (double sy : {-1.0, 1.0}) addArc(out, {sx * (L / 2 - k), sy * (0.5 - k), 0}, k, 0, 360);
            break;
        }
        case FancyOutline::Princess:
            for (double sx : {-1.0, 1.0})
                for (double sy : {-1.0, 1.0}) out.push_back({sx * L / 2, sy * 0.5, 0});
            break;
        case FancyOutline::Radiant:
            if (!(k > 0 && k < 0.5))
                throw Error("corner " + num(p.cornerPct) + ": must lie in (0, 50)% of the width");
            for (double sx : {-1.0, 1.0})
                for (double sy : {-1.0, 1.0}) {
                    out.push_back({sx * L / 2, sy * (0.5 - k), 0});
                    out.push_back({sx * (L / 2 - k), sy * 0.5, 0});
                }
            break;
    }
    return out;
}

PolygonMesh makeFancyBrilliant(const FancyBrilliantParams& p) {
    const std::vector<Vec3> outline = fancyOutline(p);
    const double R = 0.5;
    const GirdleRims rims = girdleRims(p.tiers);
    const bool pointed = p.outline == FancyOutline::Princess || p.outline == FancyOutline::Marquise ||
                         p.outline == FancyOutline::Heart;
    std::vector<NamedPlane> planes;
    for (const NamedPlane& round : roundBrilliantPlanes(p.tiers)) {
        const Vec3 n = round.plane.normal;
        const double slopeSin = std::hypot(n.x, n.y);
        if (slopeSin < 1e-12) {  // table and culet keep their heights
            planes.push_back(round);
        } else if (std::fabs(n.z) > 1e-12) {
            // Keep the plane's height where it crosses the girdle's edge; move it out with the outline.
            const Vec3 u{n.x / slopeSin, n.y / slopeSin, 0};
            const double z0 = n.z > 0 ? rims.upper : rims.lower;
            const double reach = (round.plane.offset - n.z * z0) / slopeSin;
            // Rounded outlines move each plane out by the outline's extra reach; pointed ones scale it, which
            // keeps more of the small facets near the points.
            const double extra = support(outline, u);
            const double moved = pointed ? reach * extra / R : reach + extra - R;
            planes.push_back({{n, slopeSin * moved + n.z * z0}, round.name});
        }
    }
    const int sides = girdleSideCount(p.tiers);
    for (int k = 0; k < sides; ++k) {
        const double az = 2 * kPi * k / sides;
        const Vec3 u{std::cos(az), std::sin(az), 0};
        planes.push_back({{u, support(outline, u)}, "girdle_" + std::to_string(k + 1)});
    }
    return intersectHalfSpaces(planes);
}

}  // namespace facetlight
