// The service in-process: a Service on a free loopback port over a fresh data folder, driven by an
// httplib::Client through every route, state transition and error.
#include <arpa/inet.h>
#include <netinet/in.h>
#include <sys/socket.h>
#include <unistd.h>

#include <chrono>
#include <filesystem>
#include <fstream>
#include <functional>
#include <iterator>
#include <map>
#include <regex>
#include <set>
#include <thread>

#include <gtest/gtest.h>

#include <httplib.h>
#include "optics/absorption.h"

#include "service.h"
#include "sweep/sweep_figures.h"
#include "util/simd_target.h"

namespace facetlight::server {
namespace {

namespace fs = std::filesystem;
using nlohmann::json;

constexpr const char* kJson = "application/json";
// A unit cube, outward faces: the smallest closed stone.
constexpr const char* kCubeObj =
    "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nv 0 0 1\nv 1 0 1\nv 1 1 1\nv 0 1 1\n"
    "f 1 4 3 2\nf 5 6 7 8\nf 1 2 6 5\nf 2 3 7 6\nf 3 4 8 7\nf 4 1 5 8\n";

class ServiceTest : public ::testing::Test {
  protected:
    void SetUp() override {
        dir_ = fs::temp_directory_path() / ("facetlight_api_test_" + std::to_string(::getpid()) + "_" +
                                            ::testing::UnitTest::GetInstance()->current_test_info()->name());
        fs::remove_all(dir_);
        start();
    }
    void TearDown() override {
        stopService();
        fs::remove_all(dir_);
    }
    void start(ServiceLimits limits = {}, std::optional<CostRates> costRates = {}) {
        ServiceConfig config;
        config.costRates = costRates;
        config.dataDir = dir_ / "data";
        config.meshesDir = dir_ / "meshes";
        config.webDir = "";
        config.threeDir = threeDir_;
        config.limits = limits;
        config.cores = 2;
        config.accessLog = false;
        service_ = std::make_unique<Service>(config);
        port_ = service_->bindToAnyPort("127.0.0.1");
        ASSERT_GT(port_, 0);
        listener_ = std::thread([this] { service_->listen(); });
        client_ = std::make_unique<httplib::Client>("127.0.0.1", port_);
        client_->set_read_timeout(30, 0);
    }
    void stopService() {
        if (!service_) return;
        service_->stop();
        listener_.join();
        service_.reset();
    }
    fs::path threeDir_;  // the folder served at /vendor/three/; none unless a test makes one
    httplib::Result submit(const json& job) { return client_->Post("/api/jobs", job.dump(), kJson); }
    std::string submitOk(const json& job) {
        auto r = submit(job);
        EXPECT_TRUE(r);
        EXPECT_EQ(r->status, 202) << r->body;
        return json::parse(r->body)["id"];
    }
    json status(const std::string& id) {
        auto r = client_->Get("/api/jobs/" + id);
        EXPECT_TRUE(r && r->status == 200);
        return json::parse(r->body);
    }
    // Polls until the job leaves queued/running (the worker is real; this waits on it, asserting nothing
    // about time).
    json waitFinished(const std::string& id) {
        for (;;) {
            json s = status(id);
            if (s["state"] != "queued" && s["state"] != "running") return s;
            std::this_thread::sleep_for(std::chrono::milliseconds(20));
        }
    }
    json waitState(const std::string& id, const std::string& state) {
        for (;;) {
            json s = status(id);
            if (s["state"] == state) return s;
            std::this_thread::sleep_for(std::chrono::milliseconds(10));
        }
    }
    static void expectProblem(const httplib::Result& r, int status, const std::string& field = {}) {
        ASSERT_TRUE(r);
        EXPECT_EQ(r->status, status) << r->body;
        EXPECT_EQ(r->get_header_value("Content-Type"), "application/problem+json");
        const json p = json::parse(r->body);
        EXPECT_EQ(p["status"], status);
        EXPECT_FALSE(p["detail"].get<std::string>().empty());
        if (!field.empty()) {
            EXPECT_EQ(p.value("field", ""), field) << r->body;
        }
    }

    // Sends raw bytes (what httplib::Client would not send) and returns the response's status code.
    int rawStatus(const std::string& request) const {
        const int fd = ::socket(AF_INET, SOCK_STREAM, 0);
        sockaddr_in addr{};
        addr.sin_family = AF_INET;
        addr.sin_port = htons(uint16_t(port_));
        addr.sin_addr.s_addr = htonl(INADDR_LOOPBACK);
        if (::connect(fd, reinterpret_cast<sockaddr*>(&addr), sizeof addr) != 0) {
            ::close(fd);
            return -1;
        }
        ::send(fd, request.data(), request.size(), MSG_NOSIGNAL);
        char buf[256] = {};
        const ssize_t n = ::recv(fd, buf, sizeof buf - 1, 0);
        ::close(fd);
        if (n < 12) return -1;
        return std::atoi(buf + 9);  // "HTTP/1.1 413 ..."
    }

    static json smallJob() { return {{"mesh", "round_brilliant"}, {"photons", 20000}, {"threads", 2}}; }
    static json longJob() { return {{"mesh", "round_brilliant"}, {"photons", 100'000'000}, {"threads", 1}}; }
    // A pavilion sweep of the round brilliant: `points` points from 39 deg in steps of 0.5.
    static json sweepJob(int points, uint64_t photons) {
        return {{"mesh", "round_brilliant"},
                {"photons", photons},
                {"threads", 2},
                {"sweep",
                 {{"axes",
                   {{{"name", "pavilion"}, {"from", 39}, {"to", 39 + 0.5 * (points - 1)}, {"step", 0.5}}}}}}};
    }
    json getJson(const std::string& path) {
        auto r = client_->Get(path);
        EXPECT_TRUE(r && r->status == 200) << path;
        return r ? json::parse(r->body) : json();
    }
    // sweep.json without its `timing`: what a sweep computes, which must not depend on how it ran.
    json sweepWithoutTiming(const std::string& id) {
        json sweep = getJson("/api/jobs/" + id + "/sweep.json");
        sweep.erase("timing");
        return sweep;
    }

    fs::path dir_;
    std::unique_ptr<Service> service_;
    std::thread listener_;
    int port_ = 0;
    std::unique_ptr<httplib::Client> client_;
};

TEST_F(ServiceTest, HealthAndOpenApiDescribeEveryRoute) {
    auto h = client_->Get("/healthz");
    ASSERT_TRUE(h);
    EXPECT_EQ(h->status, 200);
    EXPECT_EQ(json::parse(h->body)["status"], "ok");
    EXPECT_EQ(json::parse(h->body)["simd"], simdTarget());

    auto r = client_->Get("/api/openapi.json");
    ASSERT_TRUE(r);
    ASSERT_EQ(r->status, 200);
    const json doc = json::parse(r->body);
    EXPECT_EQ(doc["openapi"].get<std::string>().substr(0, 2), "3.");
    std::set<std::string> documented, served;
    for (const auto& [path, ops] : doc["paths"].items()) {
        for (const auto& [method, op] : ops.items()) {
            std::string m = method;
            for (char& c : m) c = char(std::toupper(static_cast<unsigned char>(c)));
            documented.insert(m + " " + path);
        }
    }
    for (const Route& route : Api::routes()) served.insert(route.method + " " + route.path);
    EXPECT_EQ(documented, served);
}

// The page's form starts from GET /api/defaults: exactly the settings a job that leaves them out gets.
TEST_F(ServiceTest, DefaultsAreWhatAJobThatLeavesThemOutGets) {
    auto r = client_->Get("/api/defaults");
    ASSERT_TRUE(r);
    ASSERT_EQ(r->status, 200);
    const json defaults = json::parse(r->body);
    EXPECT_EQ(defaults["threads"], 2);  // the service's cores
    EXPECT_FALSE(defaults.contains("mesh"));
    for (const char* part : {"render", "aset", "tilt_series", "fire_picture", "colour"})
        EXPECT_TRUE(defaults[part].is_object()) << part;
    const json job = {
        {"mesh", "round_brilliant"}, {"photons", defaults["photons"]}, {"render", true},
        {"aset", json::object()},    {"tilt_series", json::object()},  {"fire_picture", json::object()},
        {"colour", json::object()}};
    auto s = submit(job);
    ASSERT_TRUE(s);
    ASSERT_EQ(s->status, 202) << s->body;
    const json status = json::parse(s->body);
    client_->Post("/api/jobs/" + status["id"].get<std::string>() + "/cancel");
    json settings = status["settings"];
    EXPECT_EQ(settings["mesh"], "round_brilliant");
    EXPECT_EQ(settings["name"], "round brilliant");  // the job's default name, not a setting's
    settings.erase("mesh");
    settings.erase("name");
    EXPECT_EQ(settings, defaults);
    EXPECT_EQ(waitFinished(status["id"])["state"], "canceled");
}

// A colour by transmission as the page asks for its table: the same table a job's absorption would read, and
// a bad parameter refused by its own name.
TEST_F(ServiceTest, ColourByTransmissionGivesTheJobsTable) {
    auto r = client_->Get("/api/colour/by-transmission?transmitted_colour=%235b8fd0&path_mm=2");
    ASSERT_TRUE(r);
    ASSERT_EQ(r->status, 200) << r->body;
    EXPECT_EQ(json::parse(r->body),
              toJson(readAbsorption(json{{"transmitted_colour", "#5b8fd0"}, {"path_mm", 2}}, "absorption")));
    r = client_->Get("/api/colour/by-transmission?transmitted_colour=60,-20,15");
    ASSERT_TRUE(r);
    ASSERT_EQ(r->status, 200) << r->body;
    EXPECT_EQ(json::parse(r->body)["ordinary_per_mm"].size(), 41u);
    for (const auto& [query, field] : std::vector<std::pair<std::string, std::string>>{
             {"", "transmitted_colour"},
             {"transmitted_colour=95,80,0", "transmitted_colour"},
             {"transmitted_colour=blue", "transmitted_colour"},
             {"transmitted_colour=%23808080&path_mm=x", "path_mm"},
             {"transmitted_colour=%23808080&path_mm=0", "path_mm"},
             {"transmitted_colour=%23808080&hue=3", "hue"}}) {
        r = client_->Get("/api/colour/by-transmission?" + query);
        ASSERT_TRUE(r);
        EXPECT_EQ(r->status, 422) << query;
        const json p = json::parse(r->body);
        EXPECT_EQ(p.value("field", ""), field) << query << ": " << r->body;
        EXPECT_EQ(p.value("detail", "").find("absorption."), std::string::npos) << p.value("detail", "");
    }
    // An unknown name is refused as a name, whatever its value looks like.
    r = client_->Get("/api/colour/by-transmission?transmitted_colour=%23808080&hue=blue");
    ASSERT_TRUE(r);
    EXPECT_EQ(r->status, 422);
    EXPECT_NE(json::parse(r->body).value("detail", "").find("hue is not a parameter"), std::string::npos)
        << r->body;
}

// The page's absorption swatch sums the colour view's own tables: summed over the rows as the document says,
// a transmittance of 1 gives each illuminant's white, and D65's white is sRGB white.
TEST_F(ServiceTest, CieTablesGiveTheIlluminantsWhite) {
    auto r = client_->Get("/api/colour/cie");
    ASSERT_TRUE(r);
    ASSERT_EQ(r->status, 200);
    const json t = json::parse(r->body);
    ASSERT_EQ(t["wavelength_nm"].size(), 81u);
    EXPECT_EQ(t["wavelength_nm"][34], 550);
    EXPECT_DOUBLE_EQ(t["xyz_bar"][34][1].get<double>(), 0.9949501);  // y-bar at 550 nm, CIE 015:2018
    for (const char* name : {"D65", "A"}) {
        const json& power = t["illuminants"][name];
        ASSERT_EQ(power.size(), 81u) << name;
        double xyz[3] = {0, 0, 0}, norm = 0;
        for (size_t i = 0; i < power.size(); ++i) {
            for (int c = 0; c < 3; ++c) xyz[c] += power[i].get<double>() * t["xyz_bar"][i][c].get<double>();
            norm += power[i].get<double>() * t["xyz_bar"][i][1].get<double>();
        }
        for (int c = 0; c < 3; ++c)
            EXPECT_NEAR(xyz[c] / norm, t["white_xyz"][name][c].get<double>(), 1e-12) << name;
    }
    for (int row = 0; row < 3; ++row) {
        double v = 0;
        for (int c = 0; c < 3; ++c)
            v += t["xyz_to_linear_srgb"][row][c].get<double>() * t["white_xyz"]["D65"][c].get<double>();
        EXPECT_NEAR(v, 1, 2e-3) << row;
    }
}

TEST_F(ServiceTest, JobRunsToSuccessWithResults) {
    json job = smallJob();
    job["render"] = {{"width", 32}, {"height", 24}, {"samples", 1}, {"map_photons", 5000}};
    auto r = submit(job);
    ASSERT_TRUE(r);
    ASSERT_EQ(r->status, 202) << r->body;
    const json accepted = json::parse(r->body);
    const std::string id = accepted["id"];
    EXPECT_TRUE(std::regex_match(id, std::regex("[0-9a-f]{32}")));
    EXPECT_EQ(r->get_header_value("Location"), "/api/jobs/" + id);
    EXPECT_TRUE(accepted["state"] == "queued" || accepted["state"] == "running");

    const json done = waitFinished(id);
    ASSERT_EQ(done["state"], "succeeded") << done.dump();
    EXPECT_EQ(done["progress"]["fraction"], 1.0);
    EXPECT_EQ(done["progress"]["overall"], 1.0);
    EXPECT_EQ(done["progress"]["step"], 4);  // with render: tracing, viewing, photon map, rendering
    EXPECT_EQ(done["progress"]["steps"], 4);
    EXPECT_FALSE(done["started_at"].is_null());
    EXPECT_FALSE(done["finished_at"].is_null());
    EXPECT_EQ(done["settings"]["photons"], 20000);
    EXPECT_EQ(done["links"]["render"], "/api/jobs/" + id + "/render.png");

    auto stats = client_->Get("/api/jobs/" + id + "/stats");
    ASSERT_TRUE(stats && stats->status == 200);
    const json statsDoc = json::parse(stats->body);
    // Served with the standard errors of the shares; the stored result file is the CLI's document as it is.
    EXPECT_TRUE(statsDoc["regions"]["table"]["share_stderr"].is_number());
    EXPECT_TRUE(statsDoc["facets"][0]["leaving_share_stderr"].is_number());
    std::ifstream storedFile(dir_ / "data" / "jobs" / id / "stats.json");
    const std::string stored{std::istreambuf_iterator<char>(storedFile), {}};
    EXPECT_NE(stored.find("\"leaving_share\""), std::string::npos);
    EXPECT_EQ(stored.find("\"share_stderr\""),
              std::string::npos);  // (totals' trapped_share_stderr is the CLI's)
    EXPECT_EQ(stored.find("leaving_share_stderr"), std::string::npos);
    auto csv = client_->Get("/api/jobs/" + id + "/stats.csv");
    ASSERT_TRUE(csv && csv->status == 200);
    EXPECT_EQ(csv->get_header_value("Content-Type"), "text/csv");
    EXPECT_NE(csv->body.find("table"), std::string::npos);
    // Byte ranges, as server/openapi.json lists them: 206 with the bytes asked for, 416 past the end.
    auto head = client_->Get("/api/jobs/" + id + "/stats.csv", {{"Range", "bytes=0-2"}});
    ASSERT_TRUE(head);
    EXPECT_EQ(head->status, 206);
    EXPECT_EQ(head->body, "id,");
    // Past the end: a problem, with the file's length (cpp-httplib gave an empty text/csv body).
    auto past = client_->Get("/api/jobs/" + id + "/stats.csv", {{"Range", "bytes=99999999-"}});
    expectProblem(past, 416, "Range");
    EXPECT_EQ(past->get_header_value("Content-Range"), "bytes */" + std::to_string(csv->body.size()));
    // Only result files are served in ranges: a problem or a JSON document comes whole (it was cut to the
    // range).
    auto unknown =
        client_->Get("/api/jobs/0123456789abcdef0123456789abcdef/stats.csv", {{"Range", "bytes=0-9"}});
    expectProblem(unknown, 404);
    auto list = client_->Get("/api/jobs", {{"Range", "bytes=0-9"}});
    ASSERT_TRUE(list);
    EXPECT_EQ(list->status, 200);
    EXPECT_FALSE(json::parse(list->body, nullptr, false).is_discarded()) << list->body;
    for (const char* png : {"render.png", "heatmap.png", "angular.png"}) {
        auto p = client_->Get("/api/jobs/" + id + "/" + png);
        ASSERT_TRUE(p && p->status == 200) << png;
        EXPECT_EQ(p->get_header_value("Content-Type"), "image/png");
        ASSERT_GT(p->body.size(), 24u);
        EXPECT_EQ(p->body.substr(0, 8), std::string("\x89PNG\r\n\x1a\n", 8)) << png;
    }
    EXPECT_EQ(done["links"]["heatmap_layout"], "/api/jobs/" + id + "/heatmap.json");
    auto layout = client_->Get("/api/jobs/" + id + "/heatmap.json");
    ASSERT_TRUE(layout && layout->status == 200);
    EXPECT_EQ(layout->get_header_value("Content-Type"), "application/json");
    const json map = json::parse(layout->body);
    EXPECT_EQ(map["width"], 1100);
    size_t drawn = 0;
    for (const json& f : statsDoc["facets"]) drawn += f["region"] != "girdle";
    EXPECT_EQ(map["facets"].size(), drawn);
    // The stone in 3-D for the page: every facet the statistics count, by the same ids, in mm.
    EXPECT_EQ(done["links"]["stone"], "/api/jobs/" + id + "/stone.json");
    auto stone = client_->Get("/api/jobs/" + id + "/stone.json");
    ASSERT_TRUE(stone && stone->status == 200);
    EXPECT_EQ(stone->get_header_value("Content-Type"), "application/json");
    const json geometry = json::parse(stone->body);
    EXPECT_EQ(geometry["units"], "mm");
    ASSERT_EQ(geometry["facets"].size(), statsDoc["facets"].size());
    for (size_t i = 0; i < geometry["facets"].size(); ++i)
        EXPECT_EQ(geometry["facets"][i]["id"], statsDoc["facets"][i]["id"]);
    auto png = client_->Get("/api/jobs/" + id + "/render.png");
    const auto be32 = [&](size_t at) {
        uint32_t v = 0;
        for (size_t i = 0; i < 4; ++i) v = v << 8 | uint8_t(png->body[at + i]);
        return v;
    };
    EXPECT_EQ(be32(16), 32u);  // IHDR width
    EXPECT_EQ(be32(20), 24u);  // IHDR height
}

// The page's three.js (Debian's libjs-three) at /vendor/three/: its modules under build/ and examples/jsm/ as
// JavaScript, nothing else of the folder, nothing outside it, no listing.
TEST_F(ServiceTest, ServesThreeJsModulesAndNothingElse) {
    stopService();
    threeDir_ = dir_ / "three";
    const auto write = [](const fs::path& path, const std::string& text) {
        fs::create_directories(path.parent_path());
        std::ofstream(path) << text;
    };
    write(threeDir_ / "build/three.module.js", "export const REVISION = '111';\n");
    write(threeDir_ / "examples/jsm/controls/OrbitControls.js",
          "import * as T from '../../../build/three.module.js';\n");
    write(threeDir_ / "build/package.json", "{}");
    write(threeDir_ / "three.module.js", "// outside the served subfolders\n");
    write(threeDir_ / "examples/jsm/.hidden.js", "// a dot file\n");
    write(dir_ / "secret.js", "// outside the folder\n");
    start();
    auto three = client_->Get("/vendor/three/build/three.module.js");
    ASSERT_TRUE(three);
    EXPECT_EQ(three->status, 200);
    EXPECT_EQ(three->body, "export const REVISION = '111';\n");
    EXPECT_EQ(three->get_header_value("Content-Type"), "text/javascript");
    EXPECT_EQ(three->get_header_value("Cache-Control"), "no-cache");
    auto controls = client_->Get("/vendor/three/examples/jsm/controls/OrbitControls.js");
    ASSERT_TRUE(controls);
    EXPECT_EQ(controls->status, 200);
    for (const char* path :
         {"/vendor/three/build/package.json", "/vendor/three/three.module.js", "/vendor/three/build/",
          "/vendor/three/build", "/vendor/three/examples/jsm/.hidden.js", "/vendor/three/build/missing.js",
          "/vendor/three/build/../../secret.js", "/vendor/three/build/%2e%2e/%2e%2e/secret.js",
          "/vendor/three/build//three.module.js", "/vendor/three/build/./three.module.js"}) {
        auto r = client_->Get(path);
        ASSERT_TRUE(r) << path;
        EXPECT_EQ(r->status, 404) << path << r->body;
        EXPECT_EQ(r->body.find("outside"), std::string::npos) << path;
    }
}

TEST_F(ServiceTest, FireIsMeasuredLinkedAndServed) {
    json job = smallJob();
    job["fire"] = {{"enabled", true}, {"pupil_mm", 2}};
    const std::string id = submitOk(job);
    const json done = waitFinished(id);
    ASSERT_EQ(done["state"], "succeeded") << done.dump();
    const std::string self = "/api/jobs/" + id;
    EXPECT_EQ(done["links"]["heatmap_fire"], self + "/heatmap_fire.png");
    auto png = client_->Get(self + "/heatmap_fire.png");
    ASSERT_TRUE(png && png->status == 200);
    EXPECT_EQ(png->get_header_value("Content-Type"), "image/png");
    const json stats = json::parse(client_->Get(self + "/stats")->body);
    EXPECT_GT(stats["fire"]["pairs"].get<uint64_t>(), 0u);
    EXPECT_NEAR(stats["fire"]["pupil_deg"].get<double>(), 0.45837, 1e-5);  // 2 atan(1 / 250)
    EXPECT_EQ(stats["settings"]["fire"]["pupil_mm"], 2);

    json off = smallJob();
    off["fire"] = {{"enabled", false}};
    const json offDone = waitFinished(submitOk(off));
    ASSERT_EQ(offDone["state"], "succeeded");
    EXPECT_FALSE(offDone["links"].contains("heatmap_fire"));

    json bad = smallJob();
    bad["fire"] = {{"pupil_mm", 0}};
    expectProblem(submit(bad), 422, "fire.pupil_mm");
}

TEST_F(ServiceTest, TheDoublingIsLinkedServedAndItsFieldsChecked) {
    json job = smallJob();
    job["material"] = "zircon";
    job["optic_axis"] = {{"tilt_deg", 45}};
    job["doubling"] = {{"picture_size", 48}};
    const std::string id = submitOk(job);
    const json done = waitFinished(id);
    ASSERT_EQ(done["state"], "succeeded") << done.dump();
    const std::string self = "/api/jobs/" + id;
    EXPECT_EQ(done["links"]["doubling"], self + "/doubling.png");
    auto p = client_->Get(self + "/doubling.png");
    ASSERT_TRUE(p && p->status == 200);
    EXPECT_EQ(p->get_header_value("Content-Type"), "image/png");
    const json stats = json::parse(client_->Get(self + "/stats")->body);
    EXPECT_TRUE(stats["doubling"]["doubly_refracting"].get<bool>());
    EXPECT_GT(stats["doubling"]["table"]["median_mm"].get<double>(), 0);

    json bad = smallJob();
    bad["doubling"] = {{"picture_size", 4}};
    expectProblem(submit(bad), 422, "doubling.picture_size");
    bad["doubling"] = {{"loupe", "ten"}};
    expectProblem(submit(bad), 422, "doubling.loupe");
}

TEST_F(ServiceTest, TheColourViewIsLinkedServedAndItsFieldsChecked) {
    json job = smallJob();
    job["absorption"] = {{"wavelength_nm", {400, 700}}, {"ordinary_per_mm", {0.05, 0.5}}};
    job["colour"] = {{"picture_size", 32}, {"illuminant", "A"}};
    const std::string id = submitOk(job);
    const json done = waitFinished(id);
    ASSERT_EQ(done["state"], "succeeded") << done.dump();
    const std::string self = "/api/jobs/" + id;
    EXPECT_EQ(done["links"]["colour"], self + "/colour.png");
    auto p = client_->Get(self + "/colour.png");
    ASSERT_TRUE(p && p->status == 200);
    EXPECT_EQ(p->get_header_value("Content-Type"), "image/png");
    const json stats = json::parse(client_->Get(self + "/stats")->body);
    EXPECT_EQ(stats["colour"]["illuminant"], "A");
    EXPECT_GT(stats["colour"]["pixels"].get<uint64_t>(), 0u);
    EXPECT_LT(stats["colour"]["mean_colour"]["b"].get<double>(), 0);  // blue passes: a bluish stone

    json bad = smallJob();
    bad["colour"] = {{"illuminant", "D50"}};
    expectProblem(submit(bad), 422, "colour.illuminant");
    bad["colour"] = {{"wavelengths", 2}};
    expectProblem(submit(bad), 422, "colour.wavelengths");
    // A corundum's chromophores colour corundum only (docs/optics.md, "Corundum by its chromophores").
    bad = smallJob();
    bad["material"] = "diamond";
    bad["absorption"] = {{"corundum_ppma", {{"cr", 100}}}};
    expectProblem(submit(bad), 422, "absorption.corundum_ppma");
    bad["material"] = "ruby";
    bad["absorption"] = {{"corundum_ppma", {{"fe_ti", 20000}}}};
    expectProblem(submit(bad), 422, "absorption.corundum_ppma.fe_ti");
}

TEST_F(ServiceTest, ViewerViewsAreLinkedAndServed) {
    json job = smallJob();
    job["render"] = {{"width", 24}, {"height", 24}, {"samples", 1}, {"map_photons", 2000}};
    job["aset"] = {{"samples", 2}};
    job["tilt_series"] = {{"max_deg", 2}, {"axis_deg", 90}};
    job["fire_picture"] = {{"wavelengths", 2}};
    const std::string id = submitOk(job);
    const json done = waitFinished(id);
    ASSERT_EQ(done["state"], "succeeded") << done.dump();
    const std::string self = "/api/jobs/" + id;
    EXPECT_EQ(done["links"]["aset"], self + "/aset.png");
    EXPECT_EQ(done["links"]["tilt_animation"], self + "/tilt.webp");
    EXPECT_EQ(done["links"]["tilt_chart"], self + "/tilt.png");
    EXPECT_EQ(done["links"]["fire_picture"], self + "/fire.png");
    for (const auto& [file, type] :
         {std::pair{"aset.png", "image/png"}, std::pair{"tilt.webp", "image/webp"},
          std::pair{"tilt.png", "image/png"}, std::pair{"fire.png", "image/png"}}) {
        auto p = client_->Get(self + "/" + file);
        ASSERT_TRUE(p && p->status == 200) << file;
        EXPECT_EQ(p->get_header_value("Content-Type"), type);
    }
    const json stats = json::parse(client_->Get(self + "/stats")->body);
    EXPECT_EQ(stats["aset"]["shares"].size(), 5u);
    EXPECT_EQ(stats["tilt_series"]["frames"].size(), 5u);
    EXPECT_EQ(stats["tilt_series"]["settings"]["axis_deg"], 90);

    json bad = smallJob();
    bad["aset"] = json::object();
    expectProblem(submit(bad), 422, "aset");  // no render
    bad["render"] = true;
    bad["aset"] = {{"samples", 0}};
    expectProblem(submit(bad), 422, "aset.samples");
    bad.erase("aset");
    bad["tilt_series"] = {{"max_deg", 90}};
    expectProblem(submit(bad), 422, "tilt_series.max_deg");
    bad["tilt_series"] = {{"axis_deg", 400}};
    expectProblem(submit(bad), 422, "tilt_series.axis_deg");
    bad.erase("tilt_series");
    bad["fire_picture"] = {{"light_radius_deg", 0}};
    expectProblem(submit(bad), 422, "fire_picture.light_radius_deg");
}

TEST_F(ServiceTest, StatsOnlyJobHasNoPictures) {
    const std::string id = submitOk(smallJob());
    ASSERT_EQ(waitFinished(id)["state"], "succeeded");
    expectProblem(client_->Get("/api/jobs/" + id + "/render.png"), 404);
}

TEST_F(ServiceTest, SameSeedSameStatisticsWhateverTheThreads) {
    json a = smallJob(), b = smallJob();
    a["threads"] = 1;
    b["threads"] = 2;
    const std::string ia = submitOk(a), ib = submitOk(b);
    ASSERT_EQ(waitFinished(ia)["state"], "succeeded");
    ASSERT_EQ(waitFinished(ib)["state"], "succeeded");
    EXPECT_EQ(client_->Get("/api/jobs/" + ia + "/stats.csv")->body,
              client_->Get("/api/jobs/" + ib + "/stats.csv")->body);
}

TEST_F(ServiceTest, ThreadsAreCappedAtTheCores) {
    json job = smallJob();
    job["threads"] = 64;
    const std::string id = submitOk(job);
    const json s = waitFinished(id);
    EXPECT_EQ(s["threads"]["requested"], 64);
    EXPECT_EQ(s["threads"]["used"], 2);
    EXPECT_TRUE(s["threads"].contains("note"));
}

TEST_F(ServiceTest, CancelQueuedAndRunningJobs) {
    const std::string running = submitOk(longJob());
    const std::string queued = submitOk(smallJob());
    waitState(running, "running");
    const json q = status(queued);
    EXPECT_EQ(q["state"], "queued");
    EXPECT_EQ(q["queue_position"], 1);
    expectProblem(client_->Get("/api/jobs/" + running + "/stats"), 409);
    expectProblem(client_->Delete("/api/jobs/" + running), 409);

    auto c1 = client_->Post("/api/jobs/" + queued + "/cancel");
    ASSERT_TRUE(c1);
    EXPECT_EQ(c1->status, 200);
    EXPECT_EQ(json::parse(c1->body)["state"], "canceled");
    auto again = client_->Post("/api/jobs/" + queued + "/cancel");  // idempotent
    ASSERT_TRUE(again);
    EXPECT_EQ(again->status, 200);

    auto c2 = client_->Post("/api/jobs/" + running + "/cancel");
    ASSERT_TRUE(c2);
    EXPECT_EQ(c2->status, 202);
    EXPECT_EQ(waitFinished(running)["state"], "canceled");

    auto del = client_->Delete("/api/jobs/" + running);
    ASSERT_TRUE(del);
    EXPECT_EQ(del->status, 204);
    expectProblem(client_->Get("/api/jobs/" + running), 404);
    EXPECT_FALSE(fs::exists(dir_ / "data" / "jobs" / running));
}

TEST_F(ServiceTest, FinishedJobsCannotBeCanceledButCanBeDeleted) {
    const std::string id = submitOk(smallJob());
    ASSERT_EQ(waitFinished(id)["state"], "succeeded");
    EXPECT_TRUE(fs::exists(dir_ / "data" / "jobs" / id / "stats.json"));
    expectProblem(client_->Post("/api/jobs/" + id + "/cancel"), 409);
    auto del = client_->Delete("/api/jobs/" + id);
    ASSERT_TRUE(del);
    EXPECT_EQ(del->status, 204);
    EXPECT_FALSE(fs::exists(dir_ / "data" / "jobs" / id));
    expectProblem(client_->Delete("/api/jobs/" + id), 404);
}

TEST_F(ServiceTest, ListIsNewestFirstAndPaginated) {
    std::vector<std::string> ids;
    for (int i = 0; i < 3; ++i) ids.push_back(submitOk(smallJob()));
    auto r = client_->Get("/api/jobs?limit=2");
    ASSERT_TRUE(r && r->status == 200);
    const json page = json::parse(r->body);
    EXPECT_EQ(page["total"], 3);
    ASSERT_EQ(page["jobs"].size(), 2u);
    EXPECT_EQ(page["jobs"][0]["id"], ids[2]);
    EXPECT_EQ(page["jobs"][1]["id"], ids[1]);
    ASSERT_TRUE(page["next"].is_string());
    const json rest = json::parse(client_->Get(page["next"].get<std::string>())->body);
    ASSERT_EQ(rest["jobs"].size(), 1u);
    EXPECT_EQ(rest["jobs"][0]["id"], ids[0]);
    EXPECT_TRUE(rest["next"].is_null());
    expectProblem(client_->Get("/api/jobs?limit=0"), 400, "limit");
    expectProblem(client_->Get("/api/jobs?offset=-1"), 400, "offset");
    expectProblem(client_->Get("/api/jobs?limit=abc"), 400, "limit");
    for (const auto& id : ids) waitFinished(id);
}

// Issue 31: 40 jobs named with 900 000 characters each made a page 36 MB. Names are capped, and a page stops
// at the job that passes --max-list-bytes (here 1 byte: a job a page), its next link going on from there.
TEST_F(ServiceTest, ListPagesAreBoundedInBytesAndNamesInLength) {
    stopService();
    ServiceLimits limits;
    limits.maxListBytes = 1;
    start(limits);
    json named = smallJob();
    named["name"] = std::string(1025, 'n');
    expectProblem(submit(named), 422, "name");
    std::vector<std::string> ids;
    for (int i = 0; i < 3; ++i) ids.push_back(submitOk(smallJob()));
    std::string next = "/api/jobs?limit=100";
    for (int i = 2; i >= 0; --i) {
        const json page = getJson(next);
        EXPECT_EQ(page["total"], 3);
        ASSERT_EQ(page["jobs"].size(), 1u);
        EXPECT_EQ(page["jobs"][0]["id"], ids[size_t(i)]);
        if (i == 0) {
            EXPECT_TRUE(page["next"].is_null());
        } else {
            ASSERT_TRUE(page["next"].is_string());
            next = page["next"];
        }
    }
    for (const auto& id : ids) waitFinished(id);
}

TEST_F(ServiceTest, BadJobsAreRefusedNamingTheField) {
    expectProblem(client_->Post("/api/jobs", "{\"mesh\":", kJson), 400);
    expectProblem(client_->Post("/api/jobs", "[1,2]", kJson), 400);
    expectProblem(client_->Post("/api/jobs", "{}", kJson), 422, "mesh");
    expectProblem(submit({{"mesh", "round_brilliant"}}), 422, "photons");
    expectProblem(submit({{"mesh", 3}, {"photons", 10}}), 422, "mesh");
    expectProblem(submit({{"mesh", "no_such_cut"}, {"photons", 10}}), 422, "mesh");
    expectProblem(submit({{"mesh", "../../etc/passwd"}, {"photons", 10}}), 422, "mesh");
    expectProblem(submit({{"mesh", "/etc/passwd"}, {"photons", 10}}), 422, "mesh");
    expectProblem(submit({{"mesh", "round_brilliant"}, {"photons", -5}}), 422, "photons");
    expectProblem(submit({{"mesh", "round_brilliant"}, {"photons", "many"}}), 422, "photons");
    const auto overCap = submit({{"mesh", "round_brilliant"}, {"photons", 1e9}});
    expectProblem(overCap, 422, "photons");  // over --max-photons: the message gives this server's range
    EXPECT_EQ(json::parse(overCap->body)["detail"], "photons must be an integer between 1 and 100000000");
    expectProblem(submit({{"mesh", "round_brilliant"}, {"photons", 10}, {"threads", 0}}), 422, "threads");
    expectProblem(submit({{"mesh", "round_brilliant"}, {"photons", 10}, {"colour", "red"}}), 422, "colour");
    expectProblem(submit({{"mesh", "round_brilliant"}, {"photons", 10}, {"render", "yes"}}), 422, "render");
    expectProblem(submit({{"mesh", "round_brilliant"}, {"photons", 10}, {"render", {{"width", 3000}}}}), 422,
                  "render.width");
    expectProblem(client_->Post("/api/jobs", smallJob().dump(), "application/xml"), 415);
    // A point light inside the stone (its own or a cut of a shape) is refused now, not when the job runs.
    json inside = smallJob();
    inside["light"] = {{"model", "point"}, {"position", {0, 0, 0}}};
    expectProblem(submit(inside), 422, "light.position");
    inside["cut"] = {{"pavilion", 43}};
    expectProblem(submit(inside), 422, "light.position");
    inside["light"]["position"] = {0, 0, 10};
    EXPECT_EQ(submit(inside)->status, 202);
    expectProblem(client_->Get("/api/jobs/0123456789abcdef0123456789abcdef"), 404);
    expectProblem(client_->Get("/api/jobs/not-an-id"), 404);
    expectProblem(client_->Get("/api/jobs/" + std::string(5000, 'a')), 414);
    EXPECT_EQ(json::parse(client_->Get("/api/jobs")->body)["total"], 1);  // the one with the light outside
}

TEST_F(ServiceTest, BodyLimitsAndJsonOnly) {
    // Beyond httplib's 8 KiB cap on form bodies: the route reads its own.
    json job = smallJob();
    std::string body = job.dump();
    body.insert(body.size() - 1, std::string(10000, ' '));
    auto r = client_->Post("/api/jobs", body, kJson);
    ASSERT_TRUE(r);
    EXPECT_EQ(r->status, 202) << r->body;
    // What a page on any site may send without asking first (curl -d too): 415 (issue 31).
    expectProblem(client_->Post("/api/jobs", body, "application/x-www-form-urlencoded"), 415);
    expectProblem(client_->Post("/api/jobs", body, "text/plain"), 415);
    EXPECT_EQ(rawStatus("POST /api/jobs HTTP/1.1\r\nHost: localhost\r\nContent-Type: application/json\r\n"
                        "Content-Length: 5000000\r\n\r\n{"),
              413);
    EXPECT_EQ(rawStatus("POST /api/jobs HTTP/1.1\r\nHost: localhost\r\nContent-Type: application/json\r\n"
                        "Transfer-Encoding: chunked\r\n\r\n5\r\n{\"a\":\r\n0\r\n\r\n"),
              411);
    EXPECT_EQ(rawStatus("GET /api/jobs HTTP/1.1\r\nHost: localhost\r\nContent-Length: 12x\r\n\r\n"), 400);
    auto after = client_->Get("/healthz");  // still serving
    ASSERT_TRUE(after);
    EXPECT_EQ(after->status, 200);
    waitFinished(json::parse(r->body)["id"]);
}

TEST_F(ServiceTest, FullQueueAnswers503WithRetryAfter) {
    stopService();
    ServiceLimits limits;
    limits.maxQueued = 1;
    start(limits);
    const std::string running = submitOk(longJob());
    waitState(running, "running");
    const std::string queued = submitOk(smallJob());
    auto r = submit(smallJob());
    expectProblem(r, 503);
    EXPECT_FALSE(r->get_header_value("Retry-After").empty());
    client_->Post("/api/jobs/" + queued + "/cancel");
    client_->Post("/api/jobs/" + running + "/cancel");
    EXPECT_EQ(waitFinished(running)["state"], "canceled");
}

// Issue 18, a full disk. The store's test hook fails its writes as ENOSPC and SQLITE_FULL would; each case
// below wedged the service before: jobs stayed running or queued, cancel did nothing, DELETE answered 500.
class FullDiskTest : public ServiceTest {
  protected:
    void TearDown() override {
        simulatedFullDisk().files = false;
        simulatedFullDisk().database = false;
        ServiceTest::TearDown();
    }
    void startKeepingNothingFree() {
        stopService();
        ServiceLimits limits;
        limits.minFreeBytes = 0;  // past the guard: the disk filled between the check and the write
        start(limits);
    }
    json health() { return json::parse(client_->Get("/healthz")->body); }
    // A 5xx for a storage fault names no path of the server's (issue 18, finding 11).
    void expectNoPaths(const httplib::Result& r) const {
        ASSERT_TRUE(r);
        EXPECT_EQ(r->body.find(dir_.string()), std::string::npos) << r->body;
    }
};

TEST_F(FullDiskTest, ResultsThatCannotBeWrittenFailTheJobAndLeaveNothing) {
    startKeepingNothingFree();
    simulatedFullDisk().files = true;
    json job = smallJob();
    job["render"] = {{"width", 32}, {"height", 24}, {"samples", 1}, {"map_photons", 2000}};
    const std::string id = submitOk(job);
    const json s = waitFinished(id);
    EXPECT_EQ(s["state"], "failed");
    EXPECT_NE(s["error"].get<std::string>().find("could not store the results"), std::string::npos) << s;
    EXPECT_EQ(s["error"].get<std::string>().find(dir_.string()), std::string::npos) << s;
    EXPECT_FALSE(fs::exists(dir_ / "data" / "jobs" / id));
    expectProblem(client_->Get("/api/jobs/" + id + "/stats"), 409);
    expectNoPaths(client_->Post("/api/meshes?name=cube.obj", kCubeObj, "application/octet-stream"));
    expectProblem(client_->Post("/api/meshes?name=cube.obj", kCubeObj, "application/octet-stream"), 507);
    EXPECT_EQ(client_->Get("/api/meshes")->body.find("cube.obj"), std::string::npos);
    auto del = client_->Delete("/api/jobs/" + id);
    ASSERT_TRUE(del);
    EXPECT_EQ(del->status, 204);
}

TEST_F(FullDiskTest, EveryJobEndsAndCancelAndDeleteWorkWhenTheDatabaseCannotBeWritten) {
    startKeepingNothingFree();
    const std::string done = submitOk(smallJob());
    ASSERT_EQ(waitFinished(done)["state"], "succeeded");
    const std::string running = submitOk(longJob());
    const std::string next = submitOk(smallJob());
    const std::string canceled = submitOk(smallJob());
    waitState(running, "running");

    simulatedFullDisk().files = true;
    simulatedFullDisk().database = true;
    auto refused = submit(smallJob());
    expectProblem(refused, 507);
    expectNoPaths(refused);
    auto c = client_->Post("/api/jobs/" + canceled + "/cancel");
    ASSERT_TRUE(c);
    EXPECT_EQ(c->status, 200);
    EXPECT_EQ(json::parse(c->body)["state"], "canceled");
    auto cr = client_->Post("/api/jobs/" + running + "/cancel");
    ASSERT_TRUE(cr);
    EXPECT_EQ(cr->status, 202);
    EXPECT_EQ(waitFinished(running)["state"], "canceled");
    // The next job cannot even be recorded as running: it fails, with the reason, without running.
    const json n = waitFinished(next);
    EXPECT_EQ(n["state"], "failed");
    EXPECT_NE(n["error"].get<std::string>().find("could not record"), std::string::npos) << n;
    // Deleting frees space through the API: the results go at once, the record once the store takes writes.
    auto del = client_->Delete("/api/jobs/" + done);
    ASSERT_TRUE(del);
    EXPECT_EQ(del->status, 204);
    EXPECT_FALSE(fs::exists(dir_ / "data" / "jobs" / done));
    expectProblem(client_->Get("/api/jobs/" + done), 404);
    const json h = health();
    EXPECT_EQ(h["status"], "degraded");
    EXPECT_EQ(h["storage"]["state"], "failing") << h;
    EXPECT_EQ(json::parse(client_->Get("/api/jobs")->body)["total"], 3);

    // Space again: the worker records what it kept in memory, and a restart finds it all.
    simulatedFullDisk().files = false;
    simulatedFullDisk().database = false;
    while (health()["storage"]["state"] != "ok") std::this_thread::sleep_for(std::chrono::milliseconds(50));
    stopService();
    start();
    EXPECT_EQ(status(running)["state"], "canceled");
    EXPECT_EQ(status(canceled)["state"], "canceled");
    EXPECT_EQ(status(next)["state"], "failed");
    expectProblem(client_->Get("/api/jobs/" + done), 404);
}

TEST_F(FullDiskTest, BelowMinFreeNewWorkIsRefusedAndQueuedJobsFailWhileReadsGoOn) {
    const std::string done = submitOk(smallJob());
    ASSERT_EQ(waitFinished(done)["state"], "succeeded");
    const std::string running = submitOk(longJob());
    const std::string queued = submitOk(smallJob());
    waitState(running, "running");
    simulatedFullDisk().files = true;  // the disk reports 0 bytes free, under the default --min-free
    auto r = submit(smallJob());
    expectProblem(r, 507);
    EXPECT_FALSE(r->get_header_value("Retry-After").empty());
    expectProblem(client_->Post("/api/meshes?name=cube.obj", kCubeObj, "application/octet-stream"), 507);
    const json h = health();
    EXPECT_EQ(h["storage"]["state"], "full") << h;
    EXPECT_EQ(h["storage"]["free_bytes"], 0);
    auto stats = client_->Get("/api/jobs/" + done + "/stats");
    ASSERT_TRUE(stats);
    EXPECT_EQ(stats->status, 200);
    EXPECT_EQ(client_->Get("/api/jobs")->status, 200);
    EXPECT_EQ(client_->Post("/api/jobs/" + running + "/cancel")->status, 202);
    EXPECT_EQ(waitFinished(running)["state"], "canceled");
    const json q = waitFinished(queued);
    EXPECT_EQ(q["state"], "failed");
    EXPECT_NE(q["error"].get<std::string>().find("nearly full"), std::string::npos) << q;
    EXPECT_EQ(client_->Delete("/api/jobs/" + done)->status, 204);
}

// Issue 31, item 10: with --min-free 0 a disk without a free byte said "ok"; it takes nothing, so /healthz
// says why with 503. Below --min-free with room left, it stays 200 and degraded.
TEST_F(FullDiskTest, HealthIs503WhenTheDiskTakesNoMoreWritesWhateverMinFree) {
    startKeepingNothingFree();
    auto ok = client_->Get("/healthz");
    ASSERT_TRUE(ok);
    EXPECT_EQ(ok->status, 200);
    simulatedFullDisk().files = true;
    auto full = client_->Get("/healthz");
    ASSERT_TRUE(full);
    EXPECT_EQ(full->status, 503);
    const json h = json::parse(full->body);
    EXPECT_EQ(h["status"], "degraded");
    EXPECT_EQ(h["storage"]["state"], "full") << h;
    EXPECT_NE(h["storage"]["detail"].get<std::string>().find("no free byte"), std::string::npos) << h;
    EXPECT_EQ(h["storage"]["detail"].get<std::string>().find(dir_.string()), std::string::npos) << h;
    simulatedFullDisk().files = false;
    stopService();
    ServiceLimits limits;
    limits.minFreeBytes = uint64_t(1) << 62;  // more than any disk: short of --min-free, with room
    start(limits);
    auto shortOf = client_->Get("/healthz");
    ASSERT_TRUE(shortOf);
    EXPECT_EQ(shortOf->status, 200);
    EXPECT_EQ(json::parse(shortOf->body)["storage"]["state"], "full");
}

TEST_F(FullDiskTest, LeftoversAreRemovedAtStart) {
    const std::string id = submitOk(smallJob());
    ASSERT_EQ(waitFinished(id)["state"], "succeeded");
    stopService();
    const fs::path leftover = dir_ / "data" / "jobs" / id / "stats.csv.tmp";
    std::ofstream(leftover) << "half a file";
    const fs::path meshLeftover = dir_ / "data" / "meshes" / "0123456789abcdef0123456789abcdef.obj.tmp";
    std::ofstream(meshLeftover) << "v 0 0 0";
    start();
    EXPECT_FALSE(fs::exists(leftover));
    EXPECT_FALSE(fs::exists(meshLeftover));
    EXPECT_TRUE(fs::exists(dir_ / "data" / "jobs" / id / "stats.json"));
}

TEST_F(ServiceTest, MeshesListAndUpload) {
    auto list = client_->Get("/api/meshes");
    ASSERT_TRUE(list && list->status == 200);
    const json meshes = json::parse(list->body);
    bool found = false;
    for (const auto& m : meshes["shipped"]) {
        if (m["mesh"] != "round_brilliant") continue;
        found = m["facet_count"].get<int>() > 50;
        // The cut library's parameters, which the page's form edits: each with its default and range.
        const json pavilion = m["parameters"][2];
        EXPECT_EQ(pavilion["name"], "pavilion");
        EXPECT_EQ(pavilion["unit"], "deg");
        EXPECT_LT(pavilion["min"].get<double>(), pavilion["default"].get<double>());
        EXPECT_LT(pavilion["default"].get<double>(), pavilion["max"].get<double>());
        EXPECT_EQ(m["parameters"].back()["choices"], json({"trade", "faceter"}));
    }
    EXPECT_TRUE(found) << meshes.dump();

    auto up = client_->Post("/api/meshes?name=cube.obj", kCubeObj, "application/octet-stream");
    ASSERT_TRUE(up);
    ASSERT_EQ(up->status, 201) << up->body;
    const json cube = json::parse(up->body);
    EXPECT_EQ(cube["facet_count"], 6);
    const std::string meshId = cube["mesh"];
    const json uploaded = json::parse(client_->Get("/api/meshes")->body)["uploaded"];
    ASSERT_EQ(uploaded.size(), 1u);
    EXPECT_EQ(uploaded[0]["mesh"], meshId);
    json job = smallJob();
    job["mesh"] = meshId;
    const json done = waitFinished(submitOk(job));
    EXPECT_EQ(done["state"], "succeeded");
    EXPECT_EQ(done["name"], "cube.obj");  // an upload goes by its file name, not its id

    httplib::MultipartFormDataItems form = {{"file", kCubeObj, "../../evil name.obj", "text/plain"}};
    auto multi = client_->Post("/api/meshes", form);
    ASSERT_TRUE(multi);
    ASSERT_EQ(multi->status, 201) << multi->body;
    EXPECT_EQ(json::parse(multi->body)["file_name"], "evil_name.obj");

    std::string open = kCubeObj;
    open.erase(open.rfind("f "));
    expectProblem(client_->Post("/api/meshes?name=open.obj", open, "application/octet-stream"), 422, "file");
    expectProblem(
        client_->Post("/api/meshes?name=t.stl", std::string(84, '\0') + "\x05", "application/octet-stream"),
        422, "file");
    expectProblem(
        client_->Post("/api/meshes", std::string("\x01\x02\xff\xfe junk", 9), "application/octet-stream"),
        422, "file");
    expectProblem(client_->Post("/api/meshes?format=ply", kCubeObj, "application/octet-stream"), 422,
                  "format");
    expectProblem(client_->Post("/api/meshes", "", "application/octet-stream"), 422);
    EXPECT_EQ(
        rawStatus(
            "POST /api/meshes HTTP/1.1\r\nHost: localhost\r\nContent-Length: 17000000\r\n\r\nv 0 0 0\n"),
        413);
    expectProblem(submit({{"mesh", "0123456789abcdef0123456789abcdef"}, {"photons", 10}}), 422, "mesh");
}

// Issue 31, item 10: uploads can be deleted, except under a queued or running job, and take a bounded space.
TEST_F(ServiceTest, MeshesAreDeletedUnlessAJobUsesThem) {
    auto up = client_->Post("/api/meshes?name=cube.obj", kCubeObj, "application/octet-stream");
    ASSERT_TRUE(up && up->status == 201);
    const std::string mesh = json::parse(up->body)["mesh"];
    json job = longJob();
    job["mesh"] = mesh;
    const std::string running = submitOk(job);
    const std::string queued = submitOk(job);
    waitState(running, "running");
    expectProblem(client_->Delete("/api/meshes/" + mesh), 409);
    client_->Post("/api/jobs/" + running + "/cancel");
    EXPECT_EQ(waitFinished(running)["state"], "canceled");
    expectProblem(client_->Delete("/api/meshes/" + mesh), 409);  // the queued one still names it
    client_->Post("/api/jobs/" + queued + "/cancel");
    EXPECT_EQ(waitFinished(queued)["state"], "canceled");
    auto del = client_->Delete("/api/meshes/" + mesh);
    ASSERT_TRUE(del);
    EXPECT_EQ(del->status, 204) << del->body;
    EXPECT_EQ(json::parse(client_->Get("/api/meshes")->body)["uploaded"].size(), 0u);
    EXPECT_TRUE(fs::is_empty(dir_ / "data" / "meshes"));
    expectProblem(client_->Delete("/api/meshes/" + mesh), 404);
    expectProblem(submit({{"mesh", mesh}, {"photons", 10}}), 422, "mesh");  // its stone is forgotten too
    EXPECT_EQ(status(running)["state"], "canceled");                        // the jobs that used it stay
}

TEST_F(ServiceTest, UploadedMeshesTakeAtMostMaxMeshStore) {
    stopService();
    ServiceLimits limits;
    const size_t cube = std::string(kCubeObj).size();
    limits.maxMeshStoreBytes = 2 * cube + cube / 2;
    start(limits);
    const auto upload = [&] {
        return client_->Post("/api/meshes?name=cube.obj", kCubeObj, "application/octet-stream");
    };
    auto first = upload();
    ASSERT_TRUE(first && first->status == 201);
    ASSERT_EQ(upload()->status, 201);
    auto third = upload();
    expectProblem(third, 507, "file");
    EXPECT_NE(json::parse(third->body)["detail"].get<std::string>().find(
                  "--max-mesh-store of " + std::to_string(limits.maxMeshStoreBytes) + " bytes"),
              std::string::npos)
        << third->body;
    EXPECT_EQ(json::parse(client_->Get("/api/meshes")->body)["uploaded"].size(), 2u);
    ASSERT_EQ(client_->Delete("/api/meshes/" + json::parse(first->body)["mesh"].get<std::string>())->status,
              204);
    EXPECT_EQ(upload()->status, 201);  // deleting made room
}

// Every member of a job's status is one the OpenAPI document's JobStatus describes.
void expectDocumentedStatus(const json& status) {
    const json doc = json::parse(openApiDocument());
    const json& properties = doc["components"]["schemas"]["JobStatus"]["properties"];
    for (const auto& [key, value] : status.items()) EXPECT_TRUE(properties.contains(key)) << key;
}

// Issue 31, item 4: a job estimated over --max-job-seconds gets 422 naming its costliest part, both numbers
// and the field to lower, and nothing is stored; a job within them is accepted and shows its estimate.
TEST_F(ServiceTest, JobsEstimatedOverMaxJobSecondsAreRefusedNamingTheLargestPart) {
    json render = smallJob();
    render["render"] = {{"width", 2048}, {"height", 2048}, {"samples", 256}, {"max_depth", 64}};
    auto r = submit(render);
    expectProblem(r, 422, "render.samples");
    std::string detail = json::parse(r->body)["detail"];
    EXPECT_EQ(detail.rfind("render: about ", 0), 0u) << detail;
    EXPECT_NE(detail.find(" s of the 600 s a job may take on this server (2048x2048 pixels x 256 samples x "
                          "depth 64)"),
              std::string::npos)
        << detail;
    EXPECT_NE(detail.find("with 2 threads: lower render.samples"), std::string::npos) << detail;

    // A search for the best design whose finer rounds (each 4 x the photons) pass it.
    json search = sweepJob(11, 1'000'000);
    search["sweep"]["maximize"] = "brightness";
    search["sweep"]["refine_rounds"] = 6;
    r = submit(search);
    expectProblem(r, 422, "sweep.refine_rounds");
    detail = json::parse(r->body)["detail"];
    EXPECT_EQ(detail.rfind("search: about ", 0), 0u) << detail;
    EXPECT_EQ(getJson("/api/jobs")["total"], 0);  // nothing stored

    const json accepted = json::parse(submit(smallJob())->body);
    ASSERT_TRUE(accepted.contains("estimate_s")) << accepted;
    EXPECT_GT(accepted["estimate_s"].get<double>(), 0);
    EXPECT_LT(accepted["estimate_s"].get<double>(), 600);
    expectDocumentedStatus(accepted);
    const json done = waitFinished(accepted["id"]);
    EXPECT_EQ(done["state"], "succeeded");
    EXPECT_EQ(done["estimate_s"], accepted["estimate_s"]);
    expectDocumentedStatus(done);

    // Without a limit (0) the same render is accepted.
    stopService();
    ServiceLimits unlimited;
    unlimited.maxJobSeconds = 0;
    start(unlimited);
    const json big = json::parse(submit(render)->body);
    EXPECT_EQ(big["state"], "queued");
    EXPECT_GT(big["estimate_s"].get<double>(), 600);
    client_->Post("/api/jobs/" + big["id"].get<std::string>() + "/cancel");
}

// Issue 31: POST /api/jobs/estimate checks a job as a submission does (the same 4xx, the same field) and
// answers what it would cost and whether it would be refused for it, storing nothing.
TEST_F(ServiceTest, AnEstimateChecksAJobAsASubmissionDoesAndStoresNothing) {
    const auto estimate = [&](const json& job) {
        return client_->Post("/api/jobs/estimate", job.dump(), kJson);
    };
    const json schema = json::parse(openApiDocument())["components"]["schemas"]["JobEstimate"];
    auto r = estimate(smallJob());
    ASSERT_TRUE(r);
    ASSERT_EQ(r->status, 200) << r->body;
    const json small = json::parse(r->body);
    for (const auto& [key, value] : small.items()) EXPECT_TRUE(schema["properties"].contains(key)) << key;
    for (const auto& key : schema["required"]) EXPECT_TRUE(small.contains(key)) << key;
    EXPECT_FALSE(small["refused"].get<bool>());
    EXPECT_FALSE(small.contains("reason"));
    EXPECT_EQ(small["max_job_seconds"], 600);
    EXPECT_EQ(small["threads"], 2);
    EXPECT_GT(small["estimate_s"].get<double>(), 0);
    EXPECT_EQ(small["parts"][0]["part"], "trace");  // every job traces first
    bool listed = false;
    for (const json& part : small["parts"]) {
        EXPECT_LE(part["seconds"].get<double>(), small["largest"]["seconds"].get<double>()) << part;
        listed = listed || part == small["largest"];
    }
    EXPECT_TRUE(listed) << small;

    json render = smallJob();
    render["render"] = {{"width", 2048}, {"height", 2048}, {"samples", 256}, {"max_depth", 64}};
    r = estimate(render);
    ASSERT_TRUE(r);
    ASSERT_EQ(r->status, 200) << r->body;
    const json over = json::parse(r->body);
    EXPECT_TRUE(over["refused"].get<bool>());
    EXPECT_GT(over["estimate_s"].get<double>(), 600);
    EXPECT_EQ(over["largest"]["part"], "render");
    EXPECT_EQ(over["largest"]["field"], "render.samples");
    const auto refused = submit(render);
    expectProblem(refused, 422, "render.samples");
    EXPECT_EQ(over["reason"],
              json::parse(refused->body)["detail"]);  // the words the submission is refused with

    json inside = smallJob();
    inside["light"] = {{"model", "point"}, {"position", {0, 0, 0}}};
    json wide = smallJob();
    wide["render"] = {{"width", 3000}};
    for (const std::string& body :
         {std::string("{\"mesh\":"), std::string("[1,2]"), std::string("{}"),
          json{{"mesh", "round_brilliant"}, {"photons", -5}}.dump(),
          json{{"mesh", "no_such_cut"}, {"photons", 10}}.dump(),
          json{{"mesh", "round_brilliant"}, {"photons", 10}, {"colour", "red"}}.dump(), inside.dump(),
          wide.dump()}) {
        const auto asEstimate = client_->Post("/api/jobs/estimate", body, kJson);
        const auto asJob = client_->Post("/api/jobs", body, kJson);
        ASSERT_TRUE(asEstimate && asJob);
        EXPECT_GE(asJob->status, 400) << body;
        EXPECT_EQ(asEstimate->status, asJob->status) << body;
        EXPECT_EQ(json::parse(asEstimate->body).value("field", ""),
                  json::parse(asJob->body).value("field", ""))
            << body;
        EXPECT_EQ(asEstimate->get_header_value("Content-Type"), "application/problem+json");
    }
    expectProblem(client_->Post("/api/jobs/estimate", smallJob().dump(), "text/plain"), 415);
    EXPECT_EQ(getJson("/api/jobs")["total"], 0);  // nothing was queued or stored

    // The estimate is the one the job's status then carries.
    const json accepted = json::parse(submit(smallJob())->body);
    EXPECT_EQ(accepted["estimate_s"], small["estimate_s"]);
    waitFinished(accepted["id"]);
}

// A job that outlives twice --max-job-seconds is stopped through its cancel and fails with the reason, which
// a restart keeps. The test's rates make a minute's job look like nothing, as a slower stone than the
// calibration's could.
TEST_F(ServiceTest, AJobThatOutlivesItsBudgetIsStoppedAndFailsForGood) {
    stopService();
    ServiceLimits limits;
    limits.maxJobSeconds = 1;
    CostRates instant;
    instant.tracePhoton = instant.viewerUnit = 1e-15;
    start(limits, instant);
    const auto began = std::chrono::steady_clock::now();
    const std::string id = submitOk(longJob());
    json s;
    for (int k = 0; k < 600; ++k) {  // the job alone takes a minute or more
        s = status(id);
        if (s["state"] != "queued" && s["state"] != "running") break;
        std::this_thread::sleep_for(std::chrono::milliseconds(50));
    }
    const double took = std::chrono::duration<double>(std::chrono::steady_clock::now() - began).count();
    EXPECT_LT(s["estimate_s"].get<double>(), 1);
    ASSERT_EQ(s["state"], "failed") << s;
    const std::string error = s["error"];
    EXPECT_EQ(error.rfind("stopped: ran 2.", 0), 0u) << error;
    EXPECT_NE(error.find(" s, over its budget of 2.0 s (twice the 1.0 s a job may take on this server)"),
              std::string::npos)
        << error;
    EXPECT_GE(took, 2);
    EXPECT_LT(took, 15);
    expectDocumentedStatus(s);

    stopService();
    start(limits, instant);
    const json again = status(id);
    EXPECT_EQ(again["state"], "failed");
    EXPECT_EQ(again["error"], error);
    // The next job runs as usual.
    json quick = smallJob();
    quick["viewer"] = {{"enabled", false}};
    EXPECT_EQ(waitFinished(submitOk(quick))["state"], "succeeded");
}

// A job that gives no name is named by its design and the proportions it changes, in its status and its
// stored settings alike; a name it gives is kept.
TEST_F(ServiceTest, JobsAreNamedByTheirDesign) {
    const auto nameOf = [&](const json& job) {
        const json s = status(submitOk(job));
        EXPECT_EQ(s["name"], s["settings"]["name"]);
        return s["name"].get<std::string>();
    };
    json job = smallJob();
    job["photons"] = 1000;
    EXPECT_EQ(nameOf(job), "round brilliant");
    job["mesh"] = "round_brilliant_deep";
    EXPECT_EQ(nameOf(job), "round brilliant deep");
    job["mesh"] = "round_brilliant";
    job["cut"] = {{"pavilion", 43.5}, {"crown", 33}, {"lower_half", 77}};
    EXPECT_EQ(nameOf(job), "round brilliant C 33 P 43.5 lower half 77");
    job["name"] = "my deep stone";
    EXPECT_EQ(nameOf(job), "my deep stone");
    json sweep = sweepJob(2, 1000);
    sweep["sweep"]["set"] = {{"table", 55}};
    EXPECT_EQ(nameOf(sweep), "round brilliant T 55, sweep of pavilion");
}

TEST_F(ServiceTest, QueuedAndInterruptedJobsSurviveARestart) {
    const std::string running = submitOk(longJob());
    const std::string queued = submitOk(smallJob());
    waitState(running, "running");
    stopService();  // the running job goes back to the queue
    start();
    const json r = status(running);
    EXPECT_TRUE(r["state"] == "queued" || r["state"] == "running") << r.dump();
    EXPECT_TRUE(r["finished_at"].is_null());
    client_->Post("/api/jobs/" + running + "/cancel");
    EXPECT_EQ(waitFinished(running)["state"], "canceled");
    EXPECT_EQ(waitFinished(queued)["state"], "succeeded");
}

// A stored job that no longer reads as a job (a store another version wrote): it still lists with what was
// stored, its points answer 500 with the reason, and it fails with that reason when its turn comes.
TEST_F(ServiceTest, AStoredJobThatNoLongerReadsListsAndFailsWithTheReason) {
    const std::string running = submitOk(longJob());
    const std::string queued = submitOk(sweepJob(2, 1000));
    waitState(running, "running");
    json unreadable = status(queued)["settings"];
    unreadable["photons"] = 0;
    stopService();
    {
        Database db(dir_ / "data");
        Statement s(db.handle(), "UPDATE jobs SET request = ? WHERE id = ?");
        s.bind(1, unreadable.dump()).bind(2, queued);
        s.step();
    }
    start();
    const json listed = status(queued);
    EXPECT_EQ(listed["state"], "queued");
    EXPECT_EQ(listed["settings"], unreadable);
    expectProblem(client_->Get("/api/jobs/" + queued + "/points"), 500);
    client_->Post("/api/jobs/" + running + "/cancel");
    const json failed = waitFinished(queued);
    EXPECT_EQ(failed["state"], "failed");
    EXPECT_NE(failed["error"].get<std::string>().find("photons"), std::string::npos) << failed.dump();
}

TEST_F(ServiceTest, SweepRunsToSuccessWithPointsAndResults) {
    json job = sweepJob(3, 4000);
    job["sweep"]["set"] = {{"crown", 34}};
    const std::string id = submitOk(job);
    const json queued = status(id);
    EXPECT_EQ(queued["progress"]["points_total"], 3);
    EXPECT_EQ(queued["settings"]["sweep"]["axes"][0]["values"], json({39, 39.5, 40}));  // stored expanded
    const json done = waitFinished(id);
    ASSERT_EQ(done["state"], "succeeded") << done.dump();
    EXPECT_EQ(done["progress"]["points_done"], 3);
    EXPECT_EQ(done["progress"]["overall"], 1.0);
    const json& links = done["links"];
    for (const char* link : {"sweep", "sweep_csv", "sweep_picture", "points"})
        EXPECT_TRUE(links.contains(link)) << link;
    for (const char* link : {"stats", "stats_csv", "best", "best_obj"})
        EXPECT_FALSE(links.contains(link)) << link;

    const json sweep = getJson(links["sweep"]);
    EXPECT_EQ(sweep["shape"], "round_brilliant");
    EXPECT_EQ(sweep["fixed"]["crown"], 34);
    ASSERT_EQ(sweep["points"].size(), 3u);
    EXPECT_EQ(sweep["points"][2]["values"]["pavilion"], 40);
    EXPECT_GT(sweep["points"][2]["totals"]["weighted_return"].get<double>(), 0);
    auto csv = client_->Get(links["sweep_csv"].get<std::string>());
    ASSERT_TRUE(csv);
    EXPECT_EQ(csv->get_header_value("Content-Type"), "text/csv");
    EXPECT_EQ(std::count(csv->body.begin(), csv->body.end(), '\n'), 4);
    auto png = client_->Get(links["sweep_picture"].get<std::string>());
    ASSERT_TRUE(png);
    EXPECT_EQ(png->get_header_value("Content-Type"), "image/png");
    EXPECT_EQ(png->body.substr(1, 3), "PNG");
    const json points = getJson(links["points"]);
    EXPECT_EQ(points["points_total"], 3);
    EXPECT_EQ(points["axes"][0]["unit"], "deg");
    EXPECT_EQ(points["points"], sweep["points"]);
    // The reference designs the map would ring, at their pavilion angles.
    EXPECT_EQ(
        points["references"],
        json::parse(R"([{"shape": "round_brilliant", "label": "GIA reference", "values": {"pavilion": 40.7}},
                              {"shape": "round_brilliant_tolkowsky", "label": "Tolkowsky 1919",
                               "values": {"pavilion": 40.75}}])"));
    expectProblem(client_->Get("/api/jobs/" + id + "/stats"), 404);
    expectProblem(client_->Get("/api/jobs/" + submitOk(smallJob()) + "/points"), 404);
}

TEST_F(ServiceTest, SweepSearchLinksTheBestDesign) {
    json job = sweepJob(3, 2000);
    job["sweep"]["maximize"] = "weighted_return";
    job["sweep"]["refine_rounds"] = 1;
    job["sweep"]["constraints"] = {"total_depth<=70"};
    const json done = waitFinished(submitOk(job));
    ASSERT_EQ(done["state"], "succeeded") << done.dump();
    EXPECT_EQ(done["progress"]["steps"], 2);
    const json best = getJson(done["links"]["best"]);
    EXPECT_EQ(best["figure"], "weighted_return");
    EXPECT_EQ(best["rounds"].size(), 2u);
    EXPECT_EQ(best["best"]["photons"], 8000);
    auto obj = client_->Get(done["links"]["best_obj"].get<std::string>());
    ASSERT_TRUE(obj && obj->status == 200);
    EXPECT_EQ(obj->body.rfind("# facetlight cut round_brilliant", 0), 0u) << obj->body.substr(0, 80);
}

// Issue 27: an uploaded GemCad design (GemCad's own round brilliant, tests/data/gemcad/SRB.asc) lists its
// tiers, a search over two of them runs over HTTP, and its best design comes back as .asc that uploads again
// as the same stone.
TEST_F(ServiceTest, UploadedDesignTiersAreSweptAndTheBestComesBackAsAsc) {
    std::ifstream in(std::string(FACETLIGHT_SOURCE_DIR) + "/tests/data/gemcad/SRB.asc", std::ios::binary);
    const std::string asc((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    auto up = client_->Post("/api/meshes?name=SRB.asc", asc, "application/octet-stream");
    ASSERT_TRUE(up);
    ASSERT_EQ(up->status, 201) << up->body;
    const json design = json::parse(up->body);
    ASSERT_EQ(design["tiers"].size(), 5u) << design.dump();
    EXPECT_EQ(design["tiers"][0]["parameter"], "tier:1");
    EXPECT_EQ(design["tiers"][0]["angle_deg"], 42.5);
    EXPECT_EQ(design["facet_count"], 73);
    EXPECT_EQ(design["frame"]["file_orientation"], true);

    json job = {{"mesh", design["mesh"]},
                {"photons", 1500},
                {"threads", 2},
                {"viewer", {{"enabled", false}}},
                {"sweep",
                 {{"axes", {{{"name", "tier:1"}, {"from", 42.5}, {"to", 43.5}, {"step", 0.5}},
                            {{"name", "tier:A"}, {"values", {33, 35}}}}},
                  {"maximize", "weighted_return"},
                  {"refine_rounds", 1}}}};
    const json done = waitFinished(submitOk(job));
    ASSERT_EQ(done["state"], "succeeded") << done.dump();
    EXPECT_EQ(done["name"], "SRB.asc, sweep of tier:1 × tier:A");
    const json sweep = getJson(done["links"]["sweep"]);
    ASSERT_EQ(sweep["points"].size(), 6u);
    EXPECT_EQ(sweep["points"][0]["values"]["tier:1"], 42.5);
    auto best = client_->Get(done["links"]["best_asc"].get<std::string>());
    ASSERT_TRUE(best && best->status == 200);
    EXPECT_EQ(best->body.rfind("GemCad 5.0\n", 0), 0u) << best->body.substr(0, 80);
    auto again = client_->Post("/api/meshes?name=best.asc", best->body, "application/octet-stream");
    ASSERT_TRUE(again);
    ASSERT_EQ(again->status, 201) << again->body;
    const json reread = json::parse(again->body);
    EXPECT_EQ(reread["facet_count"], 73);
    // The same stone: the tiers at the best point's slopes, the others as designed.
    const json values = getJson(done["links"]["best"])["best"]["values"];
    std::map<std::string, double> designed;
    for (const auto& t : design["tiers"]) designed[t["parameter"]] = t["angle_deg"];
    for (const auto& tier : reread["tiers"]) {
        const std::string name = tier["parameter"];
        const double expected = values.contains(name) ? values[name].get<double>() : designed.at(name);
        EXPECT_NEAR(tier["angle_deg"].get<double>(), expected, 1e-6) << name;
    }

    // One point of it traced on its own, as the page's sweep chart does when a point is clicked: `cut` holds
    // the design's tier slopes.
    const json point = waitFinished(submitOk(
        {{"mesh", design["mesh"]}, {"photons", 1500}, {"viewer", {{"enabled", false}}}, {"cut", {{"tier:1", 43}}}}));
    ASSERT_EQ(point["state"], "succeeded") << point.dump();
    EXPECT_EQ(point["name"], "SRB.asc tier:1 43");
    const json stats = getJson(point["links"]["stats"]);
    EXPECT_NEAR(stats["cutting_sheet"]["tiers"][1]["measured_angle_deg"].get<double>(), -43, 1e-6);
    EXPECT_EQ(stats["material"]["source"], "design file");

    // A tier the design lacks is refused at submission, naming the axis or the cut.
    job["sweep"]["axes"][0]["name"] = "tier:P9";  // SRB's tiers are 1, 2, A, B, C
    expectProblem(submit(job), 422, "sweep.axes[0]");
    expectProblem(submit({{"mesh", design["mesh"]}, {"photons", 1500}, {"cut", {{"tier:P9", 42}}}}), 422,
                  "cut.tier:P9");
}

TEST_F(ServiceTest, SweepCancelsAndForgetsItsPoints) {
    const std::string id = submitOk(sweepJob(2, 50'000'000));
    waitState(id, "running");
    auto c = client_->Post("/api/jobs/" + id + "/cancel");
    ASSERT_TRUE(c);
    EXPECT_EQ(c->status, 202);
    EXPECT_EQ(waitFinished(id)["state"], "canceled");
    EXPECT_FALSE(fs::exists(dir_ / "data" / "jobs" / id));
}

// With fire on, every point of sweep.json, of the points the chart polls and of sweep.csv carries the fire
// figures, and the search takes one.
TEST_F(ServiceTest, SweepWithFireReportsFireAtEveryPoint) {
    json job = sweepJob(3, 3000);
    job["fire"] = {{"enabled", true}};
    job["sweep"]["figure"] = "coloured_return_weighted";
    job["sweep"]["maximize"] = "coloured_share";
    job["sweep"]["refine_rounds"] = 0;
    const json done = waitFinished(submitOk(job));
    ASSERT_EQ(done["state"], "succeeded") << done.dump();
    const json sweep = getJson(done["links"]["sweep"]);
    const json points = getJson(done["links"]["points"]);
    EXPECT_EQ(points["figures"], sweep["figures"]);
    EXPECT_EQ(points["points"], sweep["points"]);
    // Every figure but the colour view's.
    EXPECT_EQ(sweep["figures"].size(), sweepFigureNames().size() - sweepColourFigureNames().size());
    for (const json& p : sweep["points"]) {
        EXPECT_GT(p["fire"]["coloured_share"].get<double>(), 0) << p.dump();
        EXPECT_GT(p["fire"]["mean_separation_deg_stderr"].get<double>(), 0) << p.dump();
    }
    auto csv = client_->Get(done["links"]["sweep_csv"].get<std::string>());
    ASSERT_TRUE(csv);
    EXPECT_NE(csv->body.find(",mean_separation_deg,mean_separation_deg_stderr,"), std::string::npos);
    EXPECT_EQ(getJson(done["links"]["best"])["figure"], "coloured_share");
}

// With the job's colour object, a sweep over size carries the colour figures at every point, in sweep.json,
// the points the chart polls and sweep.csv (each with its error column); without it, or with no absorbing
// material, or along an axis the colour view does not see, the job is refused naming the field.
TEST_F(ServiceTest, SweepWithColourReportsTheColourFigures) {
    json job = {
        {"mesh", "round_brilliant"},
        {"photons", 200},
        {"threads", 2},
        {"material", "blue_sapphire"},
        {"viewer", {{"enabled", false}}},
        {"colour", {{"picture_size", 16}, {"samples", 1}, {"wavelengths", 4}}},
        {"sweep", {{"axes", {{{"name", "size_mm"}, {"values", {3, 12}}}}}, {"figure", "colour_lightness"}}}};
    const json done = waitFinished(submitOk(job));
    ASSERT_EQ(done["state"], "succeeded") << done.dump();
    const json sweep = getJson(done["links"]["sweep"]);
    EXPECT_EQ(getJson(done["links"]["points"])["figures"], sweep["figures"]);
    EXPECT_EQ(sweep["colour"]["picture_size"], 16);
    ASSERT_EQ(sweep["points"].size(), 2u);
    for (const json& p : sweep["points"])
        for (const std::string& f : sweepColourFigureNames()) {
            EXPECT_TRUE(p["colour"][f].is_number()) << p.dump();
            EXPECT_TRUE(p["colour"][f + "_stderr"].is_number()) << p.dump();
        }
    EXPECT_LT(sweep["points"][1]["colour"]["colour_lightness"].get<double>(),
              sweep["points"][0]["colour"]["colour_lightness"].get<double>());  // a larger stone is darker
    auto csv = client_->Get(done["links"]["sweep_csv"].get<std::string>());
    ASSERT_TRUE(csv);
    EXPECT_NE(csv->body.find("size_mm,"), std::string::npos);
    EXPECT_NE(csv->body.find(",colour_lightness,colour_lightness_stderr,"), std::string::npos);

    json bad = job;
    bad.erase("colour");
    expectProblem(submit(bad), 422, "sweep.figure");  // a colour figure without the colour view
    bad = job;
    bad["material"] = "quartz";
    expectProblem(submit(bad), 422, "material");  // nothing absorbs
    bad = job;
    bad["sweep"]["axes"] = {{{"name", "tilt"}, {"values", {0, 10}}}};
    expectProblem(submit(bad), 422, "sweep.axes[0]");  // the colour view has its own light
    bad = job;
    bad["colour"]["wavelengths"] = 1;
    expectProblem(submit(bad), 422, "colour.wavelengths");

    // The optic axis's colour: a uniaxial stone traced polarised, its axis tilted for an azimuth to mean
    // anything; else refused naming the axis.
    json axis = job;
    axis["sweep"]["axes"] = {{{"name", "optic_axis_tilt"}, {"values", {0, 90}}}};
    const json turned = waitFinished(submitOk(axis));
    ASSERT_EQ(turned["state"], "succeeded") << turned.dump();
    EXPECT_EQ(getJson(turned["links"]["sweep"])["points"][1]["values"]["optic_axis_tilt"], 90);
    bad = axis;
    bad["polarization"] = "off";
    expectProblem(submit(bad), 422, "sweep.axes[0]");
    bad = axis;
    bad["material"] = "diamond";
    expectProblem(submit(bad), 422, "sweep.axes[0]");
    bad = axis;
    bad["sweep"]["axes"][0]["name"] = "optic_axis_azimuth";
    expectProblem(submit(bad), 422, "sweep.axes[0]");
    bad["optic_axis"] = {{"tilt_deg", 45}};
    EXPECT_EQ(waitFinished(submitOk(bad))["state"], "succeeded") << "tilted, the azimuth turns it";
}

// A sweep stopped with the service keeps the points it finished, resumes from them after the restart (they
// are not traced again) and ends with the bits of a sweep that ran without a break; with fire on, its fire
// figures too.
TEST_F(ServiceTest, SweepResumesAfterARestartWithTheSameBits) {
    json job = sweepJob(8, 100'000);
    job["fire"] = {{"enabled", true}};
    const std::string id = submitOk(job);
    json s;
    do {
        s = status(id);
        ASSERT_NE(s["state"], "succeeded") << "the sweep finished before the test could stop it";
        std::this_thread::sleep_for(std::chrono::milliseconds(5));
    } while (s["progress"].value("points_done", 0) < 1);
    EXPECT_EQ(s["progress"]["points_total"], 8);
    EXPECT_GE(getJson("/api/jobs/" + id + "/points")["points"].size(), 1u);  // the chart fills in
    stopService();
    std::map<fs::path, fs::file_time_type> kept;
    for (const auto& e : fs::directory_iterator(dir_ / "data" / "jobs" / id))
        if (e.path().filename().string().rfind("point-0-", 0) == 0) kept[e.path()] = e.last_write_time();
    ASSERT_FALSE(kept.empty());
    ASSERT_LT(kept.size(), 8u);

    start();
    const json done = waitFinished(id);
    ASSERT_EQ(done["state"], "succeeded") << done.dump();
    for (const auto& [path, time] : kept)
        EXPECT_EQ(fs::last_write_time(path), time) << path;  // not traced again
    const json resumed = sweepWithoutTiming(id);
    EXPECT_TRUE(resumed["points"][7]["fire"].contains("coloured_share"));
    const json whole = waitFinished(submitOk(job));
    EXPECT_EQ(resumed.dump(), sweepWithoutTiming(whole["id"]).dump());
}

TEST_F(ServiceTest, BadSweepsAreRefusedNamingTheField) {
    const auto refused = [&](const std::function<void(json&)>& change, const std::string& field) {
        json job = sweepJob(3, 1000);
        change(job);
        expectProblem(submit(job), 422, field);
    };
    refused([](json& j) { j["sweep"].erase("axes"); }, "sweep.axes");
    refused([](json& j) { j["sweep"]["axes"] = json::array(); }, "sweep.axes");
    refused([](json& j) { j["sweep"]["axes"][0]["to"] = 30; }, "sweep.axes[0].to");
    refused([](json& j) { j["sweep"]["axes"][0]["step"] = 0; }, "sweep.axes[0].step");
    refused([](json& j) { j["sweep"]["axes"][0].erase("step"); }, "sweep.axes[0].step");
    refused([](json& j) { j["sweep"]["axes"][0]["values"] = {40}; }, "sweep.axes[0]");
    refused([](json& j) { j["sweep"]["axes"][0]["name"] = "sparkle"; }, "sweep.axes[0]");
    refused([](json& j) { j["sweep"]["axes"][0]["from"] = "39"; }, "sweep.axes[0].from");
    refused([](json& j) { j["sweep"]["axes"][1] = j["sweep"]["axes"][0]; }, "sweep.axes");
    refused(
        [](json& j) {
            j["sweep"]["axes"][0]["to"] = 1e6;
            j["sweep"]["axes"][0]["step"] = 1e-3;
        },
        "sweep.axes[0]");
    refused([](json& j) { j["sweep"]["figure"] = "sparkle"; }, "sweep.figure");
    refused([](json& j) { j["sweep"]["figure"] = "coloured_share"; }, "sweep.figure");  // fire is off
    refused([](json& j) { j["sweep"]["maximize"] = "mean_separation_deg"; }, "sweep.maximize");
    refused(
        [](json& j) {
            j["sweep"]["maximize"] = "leakage";
            j["sweep"]["constraints"] = {"total_depth<=62", "coloured_share>=0.1"};
        },
        "sweep.constraints[1]");
    refused([](json& j) { j["sweep"]["constraints"] = {"total_depth<=62"}; }, "sweep.constraints");
    refused(
        [](json& j) {
            j["sweep"]["maximize"] = "leakage";
            j["sweep"]["constraints"] = {"depth<=62"};
        },
        "sweep.constraints[0]");
    refused([](json& j) { j["sweep"]["set"] = {{"table", 500}}; }, "sweep.set.table");
    refused([](json& j) { j["sweep"]["bogus"] = 1; }, "sweep.bogus");
    refused([](json& j) { j["sweep"]["refine_rounds"] = 9; }, "sweep.refine_rounds");
    refused([](json& j) { j["mesh"] = "no_such_cut"; }, "mesh");
    refused([](json& j) { j["render"] = true; }, "render");
    refused([](json& j) { j["photons"] = 50'000'000; }, "photons");
    refused(
        [](json& j) {
            j["sweep"]["axes"] = {{{"name", "material"}, {"choices", {"diamond", "cubic_zirconia"}}}};
            j["sweep"]["maximize"] = "weighted_return";
        },
        "sweep.maximize");
    expectProblem(client_->Get("/api/jobs/0123456789abcdef0123456789abcdef/points"), 404);
}

}  // namespace
}  // namespace facetlight::server
