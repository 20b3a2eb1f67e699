// The settings tables: every field refuses a bad value naming its dotted path, JSON round-trips, every field
// has its CLI flag, and the API's schema (server/openapi.json) says what the tables say.
#include <cmath>
#include <fstream>
#include <functional>
#include <regex>
#include <set>
#include <sstream>

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "cli/trace_options.h"
#include "optics/material.h"
#include "render/render_settings.h"
#include "render/view_settings.h"
#include "study/job_request.h"
#include "support/expect_error.h"
#include "sweep/sweep_request.h"
#include "util/closest_name.h"
#include "util/error.h"

namespace facetlight {
namespace {

using nlohmann::json;
using settings::FieldInfo;
using settings::FieldType;

// Calls `visit(path, field)` for every leaf field under `path`.
void forEachField(const std::vector<FieldInfo>& fields, const std::string& path,
                  const std::function<void(const std::string&, const FieldInfo&)>& visit) {
    for (const FieldInfo& f : fields) {
        const std::string at = settings::fieldPath(path, f.key);
        if (f.type == FieldType::Object) {
            forEachField(*f.fields, at, visit);
        } else {
            visit(at, f);
        }
    }
}

// Every leaf of a job: the trace settings at the top, the render settings under "render", the viewer's
// views under "aset" and "tilt_series", the fire picture's under "fire_picture".
void forEachJobField(const std::function<void(const std::string&, const FieldInfo&)>& visit) {
    forEachField(traceSettingsSchema().fields(), "", visit);
    forEachField(renderSettingsSchema().fields(), "render", visit);
    forEachField(asetSettingsSchema().fields(), "aset", visit);
    forEachField(tiltSeriesSettingsSchema().fields(), "tilt_series", visit);
    forEachField(firePictureSettingsSchema().fields(), "fire_picture", visit);
    forEachField(polariscopeSettingsSchema().fields(), "polariscope", visit);
    forEachField(doublingSettingsSchema().fields(), "doubling", visit);
    forEachField(colourSettingsSchema().fields(), "colour", visit);
}

json::json_pointer pointer(const std::string& path) {
    std::string p = "/" + path;
    for (char& c : p) c = c == '.' ? '/' : c;
    return json::json_pointer(p);
}

// A value of the wrong type or out of the field's range.
std::vector<json> badValues(const FieldInfo& f) {
    switch (f.type) {
        case FieldType::Integer:
            return {"1", 1.5, double(f.maxCount) * 4 + 1e20,
                    f.minCount > 0 ? json(f.minCount - 1) : json(-1)};
        case FieldType::Number:
            return {"1", true, f.range.lo - 1, f.range.hi + 1};
        case FieldType::Boolean:
            return {1, "true"};
        case FieldType::Text:
            return {5, json::array()};
        case FieldType::Choice:
            return {"nope", 3};
        case FieldType::Vec3:
            return {json::array({0, 0}), json::array({0, "x", 0}), 2};
        case FieldType::Table:
            return {5, "x", json::array()};
        case FieldType::Object:
            break;
    }
    return {};
}

std::string errorField(const json& job) {
    return test::refusedField([&] { JobRequest::fromJson(job); });
}

TEST(SettingsSchema, ABadValueInEachFieldNamesItsDottedPath) {
    int checked = 0;
    forEachJobField([&](const std::string& path, const FieldInfo& f) {
        for (const json& bad : badValues(f)) {
            json job = {{"mesh", "round_brilliant"}, {"render", json::object()}};
            job[pointer(path)] = bad;
            EXPECT_EQ(errorField(job), path) << bad.dump();
            ++checked;
        }
    });
    EXPECT_GT(checked, 60);
    EXPECT_EQ(errorField({{"mesh", "m"}, {"light", {{"direction", {0, 0, 0}}}}}), "light.direction");
    EXPECT_EQ(errorField({{"mesh", "m"}, {"light", {{"colour", 1}}}}), "light.colour");
    EXPECT_EQ(errorField({{"mesh", "m"}, {"render", {{"camera", 5}}}}), "render.camera");
    EXPECT_EQ(errorField({{"mesh", "m"}, {"material", "unobtainium"}}), "material");
    EXPECT_EQ(errorField({{"mesh", "m"}, {"material", "unobtainium"}, {"n", 2}}), "no error");
    EXPECT_EQ(errorField({{"mesh", 3}}), "mesh");
    EXPECT_EQ(errorField({{"mesh", "m"}, {"render", "yes"}}), "render");
    EXPECT_EQ(errorField({{"mesh", "m"}, {"render", true}, {"aset", 1}}), "aset");
    EXPECT_EQ(
        errorField({{"mesh", "m"}, {"render", true}, {"tilt_series", {{"max_deg", 5}, {"step_deg", 6}}}}),
        "tilt_series.step_deg");
    EXPECT_EQ(
        errorField({{"mesh", "m"}, {"render", true}, {"tilt_series", {{"max_deg", 45}, {"step_deg", 0.2}}}}),
        "tilt_series.step_deg");
    EXPECT_EQ(
        errorField({{"mesh", "m"}, {"render", true}, {"tilt_series", {{"max_deg", 45}, {"step_deg", 0.5}}}}),
        "no error");
    // Steps so small that 2 * max / step + 1 frames overflow an int (issue 31): refused, not one frame.
    for (double step : {1e-9, 3e-8, 5e-324})
        EXPECT_EQ(
            errorField(
                {{"mesh", "m"}, {"render", true}, {"tilt_series", {{"max_deg", 45}, {"step_deg", step}}}}),
            "tilt_series.step_deg")
            << step;
    EXPECT_EQ(errorField({{"mesh", "m"}, {"tilt_series", json::object()}}), "tilt_series");
    EXPECT_EQ(errorField({{"mesh", "m"}, {"fire_picture", true}, {"render", true}}), "fire_picture");
    EXPECT_EQ(errorField({{"mesh", "m"}, {"fire_picture", json::object()}}), "fire_picture");  // no render
    // A shape's parameters are fields of `cut`, each named by its own path.
    EXPECT_EQ(errorField({{"mesh", "round_brilliant"}, {"cut", {{"pavilion", 89}}}}), "cut.pavilion");
    EXPECT_EQ(errorField({{"mesh", "round_brilliant"}, {"cut", {{"halves", 0.5}}}}), "cut.halves");
    EXPECT_EQ(errorField({{"mesh", "round_brilliant"}, {"cut", {{"pavillion", 41}}}}), "cut.pavillion");
    EXPECT_EQ(errorField({{"mesh", "round_brilliant"}, {"cut", 5}}), "cut");
}

std::string errorText(const json& job) {
    try {
        JobRequest::fromJson(job);
    } catch (const Error& e) {
        return e.what();
    }
    return "no error";
}

TEST(SettingsSchema, AMistypedNameIsToldTheNameItMeant) {
    const std::vector<std::string> names{"photons", "pavilion", "crown", "threads"};
    EXPECT_EQ(closestName("pavillion", names), "pavilion");
    EXPECT_EQ(closestName("PHOTON", names), "photons");
    EXPECT_EQ(closestName("therads", names), "threads");  // two letters swapped: one edit
    EXPECT_EQ(closestName("tbale", names), std::nullopt);
    EXPECT_EQ(closestName("", names), std::nullopt);
    EXPECT_EQ(closestName(std::string(100000, 'p'), names), std::nullopt);
    EXPECT_EQ(didYouMean("crwn", names), "; did you mean 'crown'?");
    EXPECT_EQ(didYouMean("zzzzz", names), "");
    EXPECT_EQ(errorText({{"mesh", "m"}, {"photon", 1000}}), "unknown field 'photon'; did you mean 'photons'?");
    EXPECT_EQ(errorText({{"mesh", "m"}, {"light", {{"modle", "hemisphere"}}}}),
              "unknown field 'light.modle'; did you mean 'light.model'?");
    EXPECT_THAT(errorText({{"mesh", "round_brilliant"}, {"cut", {{"pavillion", 41}}}}),
                testing::HasSubstr("cut.pavillion: round_brilliant has no parameter 'pavillion' (did you mean "
                                   "'pavilion'?); its parameters are: table, crown, pavilion"));
    const std::string longKey(100000, 'x');
    EXPECT_LT(errorText({{"mesh", "m"}, {longKey, 1}}).size(), 100u);
}

TEST(SettingsSchema, IntegerRangesAreExact) {
    const auto seed = [](const json& v) { return errorField({{"mesh", "m"}, {"seed", v}}); };
    EXPECT_EQ(seed(1.8446744073709552e19), "seed");  // 2^64 as a double: no uint64 holds it
    EXPECT_EQ(seed(1e300), "seed");
    EXPECT_EQ(seed(-0.5), "seed");
    EXPECT_EQ(seed(json(UINT64_MAX)), "no error");
    EXPECT_EQ(JobRequest::fromJson({{"mesh", "m"}, {"seed", UINT64_MAX}}).settings.trace.seed, UINT64_MAX);
    EXPECT_EQ(JobRequest::fromJson({{"mesh", "m"}, {"photons", 1e10}}).settings.trace.photons, kMaxPhotons);
    EXPECT_EQ(errorField({{"mesh", "m"}, {"photons", kMaxPhotons + 1}}), "photons");
    EXPECT_EQ(errorField({{"mesh", "m"}, {"threads", int64_t(-1)}}), "threads");
}

TEST(SettingsSchema, JsonRoundTrip) {
    JobRequest spec;
    spec.mesh = "round_brilliant";
    spec.name = "test stone";
    TraceSettings& t = spec.settings.trace;
    t.photons = 1234;
    t.threads = 3;
    t.seed = UINT64_MAX;
    t.material = "sapphire";
    t.constantIndex = 2.5;
    t.dispersion = false;
    t.maxBounces = 7;
    t.intersector = IntersectorKind::Embree;
    t.polarization =
        PolarizationMode::On;  // the default, which the polariser below needs: off is checked last
    t.opticAxis = {60, 120};
    t.light = {LightModelKind::Point, {1, 2, -3}, 12.5, 30, SkyKind::Cosine, {4, 5, 60}, 45};
    t.fire = {true, 3, 400};
    t.sizeMm = 8;
    t.absorption = AbsorptionSpectrum{{400, 700}, {0.5, 0.25}, {}};  // one spectrum: n makes it isotropic
    t.viewer = ViewerSettings::forSetUp(ViewerSetUp::Close);
    t.viewer.enabled = false;
    t.viewer.distanceMm = 300;
    t.viewer.pupilMm = 3;
    t.viewer.headWidthMm = 150;
    t.viewer.shoulderWidthMm = 380;
    t.viewer.shoulderDropMm = 280;
    t.viewer.shoulderBackMm = 90;
    t.viewer.rockDeg = 20;
    t.viewer.tilts = 5;
    t.viewer.azimuths = 3;
    t.viewer.sparkleStepDeg = 0.5;
    t.viewer.office = {DomeProfile::Overcast, 0.3, 5000};
    t.viewer.spot = {4, 60, 25, 200000};
    spec.settings.render = RenderSettings{64, 48, 2, 5, 5000, {45, -30, 6, 33}};
    spec.settings.aset = AsetSettings{20, 40, 3, true};
    spec.settings.tiltSeries = TiltSeriesSettings{5, 0.5, 90};
    spec.settings.firePicture = FirePictureSettings{7, 35, 2.5, 0.1};
    spec.settings.polariscope = PolariscopeSettings{12, 5000, 64};
    spec.settings.doubling = DoublingSettings{96, 15, 5};
    spec.settings.colour = ColourSettings{64, 3, 8, Illuminant::A, 20, 0.5, 25, 30};
    const json written = toJson(spec);
    const JobRequest back = JobRequest::fromJson(written);
    EXPECT_EQ(toJson(back), written);
    EXPECT_EQ(back.settings.trace.seed, UINT64_MAX);
    EXPECT_EQ(back.settings.render->camera.fovDeg, 33);
    // Every field is written, and each differs from its default, so none is lost on the way.
    forEachJobField([&](const std::string& path, const FieldInfo&) {
        ASSERT_TRUE(written.contains(pointer(path))) << path;
        JobRequest defaults;
        defaults.settings.render.emplace();
        defaults.settings.aset.emplace();
        defaults.settings.tiltSeries.emplace();
        defaults.settings.firePicture.emplace();
        // custom_material replaces material and n, which are set here, and optic_axis.rotation_deg needs a
        // biaxial material (sapphire here): they round-trip below.
        if (path != "polarization" && path != "custom_material" && path != "optic_axis.rotation_deg") {
            EXPECT_NE(written[pointer(path)], toJson(defaults)[pointer(path)]) << path;
        }
    });
    JobRequest own = spec;
    own.settings.trace.material = "auto";
    own.settings.trace.constantIndex.reset();
    MaterialDefinition tanzanite;
    tanzanite.name = "tanzanite";
    tanzanite.alpha = 1.692;
    tanzanite.beta = 1.693;
    tanzanite.gamma = 1.7;
    tanzanite.densityGcm3 = 3.35;
    own.settings.trace.customMaterial = tanzanite;
    EXPECT_EQ(JobRequest::fromJson(toJson(own)).settings.trace.customMaterial,
              own.settings.trace.customMaterial);
    EXPECT_NE(toJson(own)["custom_material"], nullptr);
    JobRequest biaxial = spec;
    biaxial.settings.trace.material = "topaz";
    biaxial.settings.trace.constantIndex.reset();
    biaxial.settings.trace.opticAxis.rotationDeg = 75;
    EXPECT_EQ(JobRequest::fromJson(toJson(biaxial)).settings.trace.opticAxis.rotationDeg, 75);
    spec.settings.render.reset();
    spec.settings.aset.reset();
    spec.settings.tiltSeries.reset();
    spec.settings.firePicture.reset();
    EXPECT_EQ(toJson(JobRequest::fromJson(toJson(spec))), toJson(spec));
    t.polarization = PolarizationMode::Off;
    t.light.polarizerDeg.reset();
    const JobRequest unpolarised = JobRequest::fromJson(toJson(spec));
    EXPECT_EQ(unpolarised.settings.trace.polarization, PolarizationMode::Off);
    EXPECT_EQ(toJson(unpolarised), toJson(spec));
}

TEST(SettingsSchema, EveryFieldHasItsCliFlag) {
    CLI::App app;
    cli::TraceOptions trace;
    cli::addTraceOptions(&app, trace);
    cli::SettingsFlags render, aset, tilt;
    render.add(&app, renderSettingsSchema().fields(), toJson(RenderSettings{}), "render");
    aset.add(&app, asetSettingsSchema().fields(), toJson(AsetSettings{}), "aset");
    tilt.add(&app, tiltSeriesSettingsSchema().fields(), toJson(TiltSeriesSettings{}), "tilt_series");
    cli::SettingsFlags fire;
    fire.add(&app, firePictureSettingsSchema().fields(), toJson(FirePictureSettings{}), "fire_picture");
    cli::SettingsFlags polariscope;  // the polariscope command's
    polariscope.add(&app, polariscopeSettingsSchema().fields(), polariscopeSettingsSchema().write(PolariscopeSettings{}),
                    "polariscope");
    cli::SettingsFlags doubling;  // the doubling command's
    doubling.add(&app, doublingSettingsSchema().fields(), doublingSettingsSchema().write(DoublingSettings{}),
                 "doubling");
    cli::SettingsFlags colour;  // the render command's
    colour.add(&app, colourSettingsSchema().fields(), colourSettingsSchema().write(ColourSettings{}),
               "colour");
    std::set<std::string> flags;
    forEachJobField([&](const std::string& path, const FieldInfo& f) {
        EXPECT_NE(app.get_option_no_throw(f.doc.flag), nullptr) << path;
        EXPECT_FALSE(f.doc.help.empty()) << path;
        EXPECT_TRUE(flags.insert(f.doc.flag).second) << "two fields share " << f.doc.flag;
        if (!f.doc.formerFlag.empty()) {
            EXPECT_EQ(app.get_option_no_throw(f.doc.formerFlag), app.get_option_no_throw(f.doc.flag)) << path;
            EXPECT_TRUE(flags.insert(f.doc.formerFlag).second) << "two fields share " << f.doc.formerFlag;
        }
    });
    app.parse(std::vector<std::string>{"90", "--tilt-axis", "4", "--tilt-series", "--aset-white-leakage", "1",
                                       "0", "0", "--light-direction", "30", "--fov", "point", "--light",
                                       "1e6", "--photons", "round_brilliant", "--mesh"});
    const TraceSettings t = cli::toTraceSettings(trace);
    EXPECT_EQ(t.photons, 1'000'000u);
    EXPECT_EQ(t.light.model, LightModelKind::Point);
    EXPECT_EQ(t.light.direction.x, 0);
    EXPECT_EQ(t.light.direction.z, 1);
    RenderSettings r;
    render.apply(renderSettingsSchema(), r);
    EXPECT_EQ(r.camera.fovDeg, 30);
    EXPECT_TRUE(aset.given());
    AsetSettings a;
    aset.apply(asetSettingsSchema(), a);
    EXPECT_TRUE(a.whiteLeakage);
    EXPECT_EQ(a.samples, 8);
    TiltSeriesSettings ts;
    tilt.apply(tiltSeriesSettingsSchema(), ts);
    EXPECT_EQ(ts.maxDeg, 4);
    EXPECT_EQ(ts.axisDeg, 90);

    CLI::App bad;
    cli::TraceOptions badTrace;
    cli::addTraceOptions(&bad, badTrace);
    bad.parse(std::vector<std::string>{"95", "--tilt", "m", "--mesh"});  // the stone tilt's former name
    try {
        cli::toTraceSettings(badTrace);
        FAIL();
    } catch (const Error& e) {
        EXPECT_EQ(std::string(e.what()), "--stone-tilt must be a number from -90 to 90 (got '95')");
    }
    CLI::App tilted;
    cli::TraceOptions tiltedTrace;
    cli::addTraceOptions(&tilted, tiltedTrace);
    tilted.parse(std::vector<std::string>{"12", "--tilt", "m", "--mesh"});
    EXPECT_EQ(cli::toTraceSettings(tiltedTrace).light.tiltDeg, 12);
    CLI::App badTilt;
    cli::SettingsFlags tooFine;
    tooFine.add(&badTilt, tiltSeriesSettingsSchema().fields(), toJson(TiltSeriesSettings{}), "tilt_series");
    badTilt.parse(std::vector<std::string>{"0.01", "--tilt-step"});
    TiltSeriesSettings fine;
    try {
        tooFine.apply(tiltSeriesSettingsSchema(), fine);
        FAIL();
    } catch (const Error& e) {
        EXPECT_EQ(std::string(e.what()).rfind("--tilt-step", 0), 0u) << e.what();
    }
}

// The OpenAPI schema of one field, as the table gives it.
void expectOpenApiAgrees(const json& api, const FieldInfo& f, const std::string& path) {
    SCOPED_TRACE(path);
    switch (f.type) {
        case FieldType::Integer:
            EXPECT_EQ(api.value("type", ""), "integer");
            EXPECT_EQ(api.value("minimum", json()), json(f.minCount));
            EXPECT_EQ(api.value("maximum", json()), json(f.maxCount));
            break;
        case FieldType::Number:
            EXPECT_EQ(api.value("type", ""), "number");
            EXPECT_EQ(api.value("nullable", false), f.nullable);
            EXPECT_EQ(api.value("minimum", json()), std::isfinite(f.range.lo) ? json(f.range.lo) : json());
            EXPECT_EQ(api.value("maximum", json()), std::isfinite(f.range.hi) ? json(f.range.hi) : json());
            EXPECT_EQ(api.value("exclusiveMinimum", false), f.range.openLo);
            EXPECT_EQ(api.value("exclusiveMaximum", false), f.range.openHi);
            break;
        case FieldType::Boolean:
            EXPECT_EQ(api.value("type", ""), "boolean");
            break;
        case FieldType::Text:
            EXPECT_EQ(api.value("type", ""), "string");
            EXPECT_FALSE(api.contains("enum"));
            EXPECT_EQ(api.value("maxLength", json()), json(settings::kMaxTextBytes));
            break;
        case FieldType::Choice:
            EXPECT_EQ(api.value("type", ""), "string");
            EXPECT_EQ(api.value("enum", json()), json(f.choices));
            break;
        case FieldType::Vec3:
            EXPECT_EQ(api.value("$ref", ""), "#/components/schemas/Vec3");
            break;
        case FieldType::Table:
            EXPECT_EQ(api.value("nullable", false), true);
            EXPECT_EQ(api.at("allOf").at(0).value("$ref", ""), "#/components/schemas/" + f.ref);
            break;
        case FieldType::Object: {
            EXPECT_EQ(api.value("type", ""), "object");
            EXPECT_EQ(api.value("additionalProperties", true), false);
            const json& properties = api.at("properties");
            EXPECT_EQ(properties.size(), f.fields->size());
            for (const FieldInfo& sub : *f.fields) {
                ASSERT_TRUE(properties.contains(sub.key)) << sub.key;
                expectOpenApiAgrees(properties[sub.key], sub, settings::fieldPath(path, sub.key));
            }
            break;
        }
    }
}

TEST(SettingsSchema, OpenApiAgreesWithTheTables) {
    std::ifstream in(FACETLIGHT_SOURCE_DIR "/server/openapi.json");
    const json api = json::parse(in);
    const json& job = api["components"]["schemas"]["JobRequest"];
    const json& properties = job["properties"];
    std::set<std::string> keys = {"mesh", "name", "render", "sweep", "cut"};
    for (const FieldInfo& f : traceSettingsSchema().fields()) {
        keys.insert(f.key);
        ASSERT_TRUE(properties.contains(f.key)) << f.key;
        expectOpenApiAgrees(properties[f.key], f, f.key);
    }
    std::set<std::string> documented;
    for (const auto& [key, value] : properties.items()) documented.insert(key);
    FieldInfo render = settings::describe("render", FieldType::Object);
    render.fields = &renderSettingsSchema().fields();
    expectOpenApiAgrees(properties["render"]["oneOf"][1], render, "render");
    FieldInfo aset = settings::describe("aset", FieldType::Object);
    aset.fields = &asetSettingsSchema().fields();
    keys.insert("aset");
    expectOpenApiAgrees(properties["aset"], aset, "aset");
    FieldInfo tilt = settings::describe("tilt_series", FieldType::Object);
    tilt.fields = &tiltSeriesSettingsSchema().fields();
    keys.insert("tilt_series");
    expectOpenApiAgrees(properties["tilt_series"], tilt, "tilt_series");
    FieldInfo fire = settings::describe("fire_picture", FieldType::Object);
    fire.fields = &firePictureSettingsSchema().fields();
    keys.insert("fire_picture");
    expectOpenApiAgrees(properties["fire_picture"], fire, "fire_picture");
    FieldInfo polariscope = settings::describe("polariscope", FieldType::Object);
    polariscope.fields = &polariscopeSettingsSchema().fields();
    keys.insert("polariscope");
    expectOpenApiAgrees(properties["polariscope"], polariscope, "polariscope");
    FieldInfo doubling = settings::describe("doubling", FieldType::Object);
    doubling.fields = &doublingSettingsSchema().fields();
    keys.insert("doubling");
    expectOpenApiAgrees(properties["doubling"], doubling, "doubling");
    FieldInfo colour = settings::describe("colour", FieldType::Object);
    colour.fields = &colourSettingsSchema().fields();
    keys.insert("colour");
    expectOpenApiAgrees(properties["colour"], colour, "colour");
    EXPECT_EQ(documented, keys);
}

// A sweep's object (core/sweep/sweep_request.h) has the keys its table reads, no more.
TEST(SettingsSchema, OpenApiSweepAgreesWithItsTable) {
    std::ifstream in(FACETLIGHT_SOURCE_DIR "/server/openapi.json");
    const json api = json::parse(in);
    const json& sweep = api["components"]["schemas"]["SweepRequest"];
    EXPECT_EQ(api["components"]["schemas"]["JobRequest"]["properties"]["sweep"]["$ref"],
              "#/components/schemas/SweepRequest");
    EXPECT_EQ(sweep.value("additionalProperties", true), false);
    std::set<std::string> documented, read;
    for (const auto& [key, value] : sweep["properties"].items()) documented.insert(key);
    for (const FieldInfo& f : sweepRequestSchema().fields()) read.insert(f.key);
    EXPECT_EQ(documented, read);
    EXPECT_EQ(sweep["properties"]["figure"]["enum"], json(sweepFigureNames()));
    EXPECT_EQ(sweep["properties"]["maximize"]["enum"], json(sweepFigureNames()));
}

// Every material the settings accept is offered where a job is written by hand: the API's description of
// `material` and the page's material menu.
TEST(SettingsSchema, ApiAndPageOfferEveryMaterial) {
    std::ifstream in(FACETLIGHT_SOURCE_DIR "/server/openapi.json");
    const json api = json::parse(in);
    const std::string description =
        api["components"]["schemas"]["JobRequest"]["properties"]["material"]["description"].get<std::string>();
    std::ifstream page(FACETLIGHT_SOURCE_DIR "/web/index.html");
    std::stringstream html;
    html << page.rdbuf();
    for (const std::string& name : materialNames()) {
        EXPECT_TRUE(std::regex_search(description, std::regex("\\b" + name + "\\b"))) << name;
        EXPECT_NE(html.str().find("<option value=\"" + name + "\""), std::string::npos) << name;
    }
}

}  // namespace
}  // namespace facetlight
