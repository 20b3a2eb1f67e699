#include "viewer/doubling.h"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "optics/material.h"
#include "scene/scene.h"
#include "trace/trace_base.h"
#include "util/number_text.h"
#include "util/parallel.h"

namespace facetlight {
namespace {

// Snell's law in vector form from outside (eta = 1 / n) through a facet of outward unit normal `normal`.
Vec3 refractInto(const Vec3& d, const Vec3& normal, double eta) {
    const double cosI = -dot(d, normal);
    const double cosT = std::sqrt(std::max(0.0, 1 - eta * eta * (1 - cosI * cosI)));
    return d * eta + normal * (eta * cosI - cosT);
}

// Where a ray from p along r meets the plane of facet f.
Vec3 onPlane(const Facet& f, const Vec3& p, const Vec3& r) {
    return p + r * ((f.offset - dot(f.normal, p)) / dot(f.normal, r));
}

// The distance between the two images of one pavilion point, in the image plane (axes u, v, line of sight
// `view`), for a pixel whose ray enters through facet `entry` and whose ordinary and extraordinary waves meet
// facet `pavilion` at po and pe. Within one pair of planar facets the extraordinary image of the pavilion is
// an affine map of the image plane, X(u) = pe + J (u - u0): the pavilion point po is seen through the
// extraordinary wave at u0 + J^-1 (po - pe), so that is the doubling (J: the image plane moved along the line
// of sight onto the entry facet, then along the wave onto the pavilion facet; pavilion points are read by
// their projections on u and v, a chart of the facet plane as long as the line of sight is not in it).
double imageDistance(const Facet& entry, const Facet& pavilion, const Vec3& view, const Vec3& e,
                     const Vec3& u, const Vec3& v, const Vec3& po, const Vec3& pe) {
    auto carried = [&](const Vec3& delta) {
        const Vec3 a = delta - view * (dot(entry.normal, delta) / dot(entry.normal, view));
        return a - e * (dot(pavilion.normal, a) / dot(pavilion.normal, e));
    };
    const Vec3 ju = carried(u), jv = carried(v), gap = po - pe;
    const double a = dot(ju, u), b = dot(jv, u), c = dot(ju, v), d = dot(jv, v);
    const double det = a * d - b * c;
    if (!(std::abs(det) > 1e-12)) return -1;
    const double gu = dot(gap, u), gv = dot(gap, v);
    return std::hypot((d * gu - b * gv) / det, (a * gv - c * gu) / det);
}

DoublingSpread spread(std::vector<float> mm) {
    DoublingSpread s;
    s.pixels = mm.size();
    if (mm.empty()) return s;
    std::sort(mm.begin(), mm.end());
    auto at = [&](double q) { return double(mm[size_t(q * double(mm.size() - 1) + 0.5)]); };
    s.lowMm = at(0.25);
    s.medianMm = at(0.5);
    s.highMm = at(0.75);
    return s;
}

}  // namespace

const settings::Schema<DoublingSettings>& doublingSettingsSchema() {
    using namespace settings;
    static const Schema<DoublingSettings> schema({
        count("picture_size", &DoublingSettings::pictureSize, 32, 2048,
              {"--doubling-picture", "Doubling: view rays (and pixels) across the face-up view"}),
        number(
            "tilt_deg", &DoublingSettings::tiltDeg, {.lo = -60, .hi = 60},
            {"--doubling-tilt", "Doubling: the stone tilted about its x axis, seen from above", "degrees"}),
        number("loupe", &DoublingSettings::loupe, {.lo = 1, .hi = 30},
               {"--loupe", "Doubling: the loupe's magnification for the angle the doubling subtends", "x"}),
    });
    return schema;
}

double Doubling::arcMinutes(double mm) const {
    return mm / (250.0 / loupe) * 180.0 / std::numbers::pi * 60.0;
}

Doubling doubling(const Stone& stone, const TraceSettings& settings, const DoublingSettings& d,
                  RunControl* control) {
    doublingSettingsSchema().read(doublingSettingsSchema().write(d));  // the table's checks
    TraceSettings s = settings;
    s.polarization = PolarizationMode::On;  // TraceBase's crystal and optic-axis cone
    s.dispersion = false;
    s.light = LightSettings{};
    s.light.tiltDeg = d.tiltDeg;
    s.fire.enabled = false;
    const Scene scene(stone, s);
    const TraceBase trace(scene, s);

    Doubling out;
    out.doublyRefracting = trace.birefringent();
    out.nO = scene.fixedIndex();
    out.nE = out.doublyRefracting ? trace.principalIndex(2, Material::kSodiumD) : out.nO;
    if (trace.biaxial()) out.nA = trace.principalIndex(0, Material::kSodiumD);
    out.sizeMm = s.sizeMm;
    out.diameterMm = s.sizeMm;  // the mesh is scaled so that its girdle diameter is size_mm
    out.loupe = d.loupe;
    out.tiltDeg = d.tiltDeg;
    if (trace.biaxial()) {
        out.tracedAs =
            "doubly refracting (biaxial): each view ray splits at the crown into its fast and slow "
            "waves (alpha " +
            formatNumber("%.4f", out.nA) + ", beta " + formatNumber("%.4f", out.nO) + ", gamma " +
            formatNumber("%.4f", out.nE) + ")";
    } else if (out.doublyRefracting) {
        out.tracedAs =
            "doubly refracting (uniaxial): each view ray splits at the crown into its ordinary wave (n_o " +
            formatNumber("%.4f", out.nO) + ") and its extraordinary wave (n_e " +
            formatNumber("%.4f", out.nE) + ")";
    } else {
        out.tracedAs = "singly refracting (n " + formatNumber("%.4f", out.nO) + "): one image";
    }

    // The view in the stone's frame: along -z of the world, the image plane's axes the world's x and y.
    const Vec3 view = scene.toStone({0, 0, -1}), u = scene.toStone({1, 0, 0}), v = scene.toStone({0, 1, 0});
    const Vec3 axis = s.opticAxis.direction();
    const BiaxialMedium biaxial = trace.biaxialCrystal(float(out.nA), float(out.nO), float(out.nE));
    if (trace.biaxial()) {  // the nearer of its two optic axes
        const std::array<Vec3, 2> axes = opticAxes(biaxial);
        const double c = std::max(std::abs(dot(view, axes[0])), std::abs(dot(view, axes[1])));
        out.viewToAxisDeg = degrees(std::acos(std::min(1.0, c)));
    } else if (out.doublyRefracting) {
        out.viewToAxisDeg = degrees(std::acos(std::min(1.0, std::abs(dot(view, axis)))));
    }
    const Vec3 centre = scene.center();
    double half = 0;
    for (const Vec3& p : stone.vertices)
        half = std::max({half, std::abs(dot(p - centre, u)), std::abs(dot(p - centre, v))});
    half *= 1.05;
    const double mmPerUnit = s.sizeMm / scene.diameter();
    out.size = d.pictureSize;
    out.halfWidthMm = half * mmPerUnit;
    const size_t n = size_t(d.pictureSize);
    out.entry.assign(n * n, -1);
    out.ordinary.assign(n * n, -1);
    out.extraordinary.assign(n * n, -1);
    out.doublingMm.assign(n * n, -1.0f);

    const UniaxialMedium crystal = trace.crystal(float(out.nO), float(out.nE));
    const BlockLoop loop{0, n, 8, settings.threads};
    parallelForBlocks(loop, control, [&](int, uint64_t first, uint64_t last) {
        for (uint64_t row = first; row < last; ++row)
            for (size_t col = 0; col < n; ++col) {
                const size_t k = row * n + col;
                const double x = (2 * (double(col) + 0.5) / double(n) - 1) * half;
                const double y = (1 - 2 * (double(row) + 0.5) / double(n)) * half;
                const Vec3 origin = centre + u * x + v * y - view * (3 * half);
                SurfaceHit hit;
                if (!scene.enter(Vec3f(origin), Vec3f(view), hit)) continue;
                out.entry[k] = int32_t(hit.facet);
                const Facet& entry = stone.facets[hit.facet];
                if (entry.region != Region::Table && entry.region != Region::Crown) continue;
                if (!(dot(view, entry.normal) < 0)) continue;
                const Vec3 p = onPlane(entry, origin, view);
                Vec3 o = refractInto(view, entry.normal, 1 / out.nO), e = o;
                if (trace.biaxial()) {
                    const InterfaceWaves w = enterCrystal(biaxial, view, entry.normal);
                    o = w.transmitted[0].wave.ray;
                    e = w.transmitted[1].wave.ray;
                } else if (out.doublyRefracting) {
                    const InterfaceWaves w = enterCrystal(crystal, view, entry.normal);
                    o = w.transmitted[0].wave.ray;
                    // Near the optic axis the two waves keep in step: one image, as the tracer has it.
                    e = trace.nearOpticAxis(w.transmitted[0].wave.waveNormal) ? o : w.transmitted[1].wave.ray;
                }
                auto pavilionFacet = [&](const Vec3& r) {
                    SurfaceHit h;
                    if (!scene.leave(Vec3f(p), Vec3f(r), h)) return -1;
                    return stone.facets[h.facet].region == Region::Pavilion ? int(h.facet) : -1;
                };
                const int fo = pavilionFacet(o), fe = pavilionFacet(e);
                out.ordinary[k] = fo;
                out.extraordinary[k] = fe;
                if (fo < 0 || fo != fe) continue;
                const Facet& pavilion = stone.facets[size_t(fo)];
                const double gap = imageDistance(entry, pavilion, view, e, u, v, onPlane(pavilion, p, o),
                                                 onPlane(pavilion, p, e));
                if (gap >= 0) out.doublingMm[k] = float(gap * mmPerUnit);
            }
        return (last - first) * n;
    });

    std::vector<float> table, crown;
    for (size_t k = 0; k < n * n; ++k) {
        if (out.doublingMm[k] < 0) continue;
        crown.push_back(out.doublingMm[k]);
        if (stone.facets[size_t(out.entry[k])].region == Region::Table) table.push_back(out.doublingMm[k]);
    }
    out.table = spread(std::move(table));
    out.crown = spread(std::move(crown));
    return out;
}

nlohmann::json toJson(const Doubling& d) {
    auto spreadJson = [&](const DoublingSpread& s) {
        return nlohmann::json{{"pixels", s.pixels},
                              {"median_mm", s.medianMm},
                              {"quartiles_mm", {s.lowMm, s.highMm}},
                              {"median_share_of_diameter", d.shareOfDiameter(s.medianMm)},
                              {"median_arcmin", d.arcMinutes(s.medianMm)}};
    };
    nlohmann::json j = {{"doubly_refracting", d.doublyRefracting},
                        {"traced_as", d.tracedAs},
                        {"n_o", d.nO},
                        {"n_e", d.nE},
                        {"view_to_axis_deg", d.viewToAxisDeg},
                        {"tilt_deg", d.tiltDeg},
                        {"size_mm", d.sizeMm},
                        {"loupe", d.loupe},
                        {"table", spreadJson(d.table)},
                        {"crown", spreadJson(d.crown)}};
    if (d.nA > 0) j["alpha"] = d.nA;  // a biaxial stone's (n_o and n_e are then beta and gamma)
    return j;
}

}  // namespace facetlight
