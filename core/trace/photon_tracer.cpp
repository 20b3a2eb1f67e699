#include "trace/photon_tracer.h"

#include <algorithm>
#include <chrono>

#include "trace/fire_trace.h"
#include "trace/photon_walker.h"
#include "util/parallel.h"

namespace facetlight {

void tracePhoton(const TraceBase& trace, uint64_t index, PhotonPath& out) {
    PhotonWalker::path(trace, index, out);
}

bool traceBlocks(const TraceBase& trace, uint64_t firstBlock, uint64_t lastBlock, int threads,
                 FacetStats& stats, RunControl* control, FireStats* fire) {
    const uint64_t photons = trace.settings().photons;
    lastBlock = std::min(lastBlock, blockCount(photons));
    if (firstBlock >= lastBlock) return true;
    const size_t facets = trace.scene().stone().facets.size();
    if (stats.facets.size() != facets) stats = FacetStats(facets);
    if (fire && fire->colouredByFacet.size() != facets) *fire = FireStats(facets);
    const BlockLoop loop{firstBlock * kPhotonBlock, std::min(lastBlock * kPhotonBlock, photons), kPhotonBlock,
                         threads};
    struct Tallies {
        FacetStats stats;
        FireStats fire;
    };
    const WorkerStates<Tallies> tallies =
        parallelForBlocks(loop, control, Tallies{FacetStats(facets), FireStats(fire ? facets : 0)},
                          [&](Tallies& tally, uint64_t begin, uint64_t end) {
                              if (fire) {
                                  traceFire(trace, begin, end, tally.stats, tally.fire);
                              } else {
                                  PhotonWalker::tally(trace, begin, end, tally.stats);
                              }
                              return end - begin;
                          });
    for (const Tallies& tally : tallies.states) {
        stats.merge(tally.stats);
        if (fire) fire->merge(tally.fire);
    }
    return tallies.finished;
}

nlohmann::json traceReport(const TraceResult& result, const Stone& stone, const TraceSettings& settings) {
    nlohmann::json stats = statsToJson(result.stats, stone, toJson(settings), result.timing);
    if (result.fire)
        stats["fire"] =
            fireToJson(*result.fire, stone, settings.fire.pupilAngleDeg(), settings.light.headShadowDeg);
    return stats;
}

DesignFacts designFacts(const Stone& stone, const TraceSettings& settings) {
    DesignFacts facts{chooseMaterial(settings, stone), {}, cuttingSheet(stone), std::nullopt};
    const bool polarized = settings.polarization == PolarizationMode::On;
    switch (facts.material.material.optic()) {
    case Optic::Isotropic:
        break;
    case Optic::Uniaxial:
        facts.doubleRefraction = polarized ? "traced: each ray splits into its ordinary and extraordinary waves"
                                           : "not traced: with polarization off every ray sees n_o";
        break;
    case Optic::Biaxial:
        facts.doubleRefraction =
            polarized ? "traced: each ray splits into the biaxial crystal's fast and slow waves"
                      : "not traced: with polarization off every ray sees beta";
        break;
    }
    if (stone.proportions.diameter > 0)  // else there is no girdle width to scale by
        facts.size = stoneSize(stone, settings.sizeMm, facts.material.material.densityGcm3());
    return facts;
}

void addDesignFacts(nlohmann::json& stats, const DesignFacts& facts) {
    const Material& m = facts.material.material;
    stats["material"] = {{"name", m.name()},
                         {"n_d", m.indexD()},
                         {"dispersion_bg", m.dispersionBG()},
                         {"optic", opticName(m.optic())},
                         {"birefringence", m.birefringence()},
                         {"source", facts.material.source}};
    if (!facts.doubleRefraction.empty()) stats["material"]["double_refraction"] = facts.doubleRefraction;
    if (facts.sheet) stats["cutting_sheet"] = toJson(*facts.sheet);
    if (const std::optional<StoneSize>& size = facts.size) {
        const std::optional<double> density = m.densityGcm3();
        stats["size"] = {{"size_mm", stats["settings"]["size_mm"]},
                         {"length_mm", size->lengthMm},
                         {"width_mm", size->widthMm},
                         {"depth_mm", size->depthMm},
                         {"volume_mm3", size->volumeMm3},
                         {"block_retention", size->blockRetention},
                         {"density_g_cm3", density ? nlohmann::json(*density) : nlohmann::json()},
                         {"carats", size->carats ? nlohmann::json(*size->carats) : nlohmann::json()}};
    }
}

TraceResult trace(const TraceBase& trace, RunControl* control) {
    const TraceSettings& settings = trace.settings();
    const size_t facets = trace.scene().stone().facets.size();
    TraceResult result{FacetStats(facets), {0, settings.threads}, false, std::nullopt};
    if (settings.fire.enabled) result.fire = FireStats(facets);
    const auto start = std::chrono::steady_clock::now();
    result.cancelled = !traceBlocks(trace, 0, blockCount(settings.photons), settings.threads, result.stats,
                                    control, result.fire ? &*result.fire : nullptr);
    result.timing.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    return result;
}

}  // namespace facetlight
