// The service's launcher: jobs as child processes, through mpirun on localhost and through fake launchers
// (sh -c) for the failures.
#include "launcher.h"

#include <gtest/gtest.h>
#include <signal.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <thread>

#include "cuts/mesh_resolver.h"
#include "study/study.h"
#include "util/error.h"

using namespace facetlight;
using namespace facetlight::server;
namespace fs = std::filesystem;

namespace {

const std::string kMesh = FACETLIGHT_SOURCE_DIR "/tests/data/brilliant.asc";

// mpirun refuses root (containers, CI) without these.
const bool kRootAllowed =
    setenv("OMPI_ALLOW_RUN_AS_ROOT", "1", 1) == 0 && setenv("OMPI_ALLOW_RUN_AS_ROOT_CONFIRM", "1", 1) == 0;

LaunchSettings settingsWith(std::vector<std::string> launcher) {
    LaunchSettings s;
    s.launcher = std::move(launcher);
    s.executable = FACETLIGHT_TOOL;
    s.cancelGrace = std::chrono::milliseconds(500);
    return s;
}

LaunchSettings mpirun(int ranks) {
    return settingsWith({FACETLIGHT_MPIEXEC, "--oversubscribe", "-np", std::to_string(ranks)});
}

StudySettings traceOnly(uint64_t photons) {
    StudySettings s;
    s.trace.photons = photons;
    s.trace.threads = 1;
    s.trace.seed = 5;
    return s;
}

// The job a launcher hands its child: `mesh` as the child reads it, traced with `settings`.
JobRequest childJob(std::string mesh, std::string name, StudySettings settings) {
    JobRequest spec;
    spec.mesh = std::move(mesh);
    spec.name = std::move(name);
    spec.settings = std::move(settings);
    return spec;
}

// Alive and not a zombie.
bool running(pid_t pid) {
    std::ifstream stat("/proc/" + std::to_string(pid) + "/stat");
    std::string pidText, name, state;
    return stat >> pidText >> name >> state && state != "Z";
}

pid_t readPid(const fs::path& file) {
    pid_t pid = 0;
    for (int i = 0; i < 500 && !(std::ifstream(file) >> pid); ++i)
        std::this_thread::sleep_for(std::chrono::milliseconds(10));
    return pid;
}

// Sets cancel once the job reports it is tracing.
std::thread cancelWhenTracing(RunControl& control) {
    return std::thread([&control] {
        while (control.phase() != RunPhase::Tracing)
            std::this_thread::sleep_for(std::chrono::milliseconds(5));
        control.cancel();
    });
}

nlohmann::json withoutTiming(nlohmann::json j) {
    j.erase("timing");
    return j;
}

}  // namespace

TEST(SplitWords, BlanksQuotesAndEscapes) {
    EXPECT_EQ(splitWords("  mpirun -np 4   --hostfile hosts "),
              (std::vector<std::string>{"mpirun", "-np", "4", "--hostfile", "hosts"}));
    EXPECT_EQ(splitWords(R"(a 'b c' "d \"e\"" f\ g '')"),
              (std::vector<std::string>{"a", "b c", "d \"e\"", "f g", ""}));
    EXPECT_TRUE(splitWords("   ").empty());
    EXPECT_THROW(splitWords("mpirun 'unclosed"), Error);
}

TEST(Launcher, ThresholdCountsTraceAndMapPhotons) {
    LaunchSettings launch;
    launch.minPhotons = 1000;
    StudySettings s = traceOnly(600);
    EXPECT_FALSE(useLauncher(launch, s));
    s.render = RenderSettings{};
    s.render->mapPhotons = 400;
    EXPECT_TRUE(useLauncher(launch, s));
}

TEST(Launcher, ProgressLines) {
    RunControl control;
    EXPECT_TRUE(applyProgressLine(R"({"phase":"tracing","done":5,"total":10})", control));
    EXPECT_EQ(control.phase(), RunPhase::Tracing);
    EXPECT_EQ(control.done(), 5u);
    EXPECT_EQ(control.total(), 10u);
    EXPECT_FALSE(applyProgressLine("--------------------------------------------", control));
    EXPECT_FALSE(applyProgressLine(R"({"phase":"dancing","done":1})", control));
    EXPECT_FALSE(applyProgressLine(R"({"phase": 3})", control));
    EXPECT_FALSE(applyProgressLine("{not json", control));
    EXPECT_EQ(control.done(), 5u);
}

TEST(Launcher, FailedLauncherFailsTheJobWithItsMessage) {
    RunControl control;
    const auto launch =
        settingsWith({"sh", "-c", "echo 'There are not enough slots available' >&2; exit 3", "sh"});
    try {
        runStudyInChild(launch, childJob(kMesh, "", traceOnly(1000)), control);
        FAIL() << "no error";
    } catch (const Error& e) {
        EXPECT_NE(std::string(e.what()).find("exit code 3"), std::string::npos) << e.what();
        EXPECT_NE(std::string(e.what()).find("not enough slots"), std::string::npos) << e.what();
    }
}

TEST(Launcher, MissingLauncherFailsTheJob) {
    RunControl control;
    try {
        runStudyInChild(settingsWith({"/nonexistent/mpirun", "-np", "2"}),
                        childJob(kMesh, "", traceOnly(1000)), control);
        FAIL() << "no error";
    } catch (const Error& e) {
        EXPECT_NE(std::string(e.what()).find("cannot start '/nonexistent/mpirun'"), std::string::npos)
            << e.what();
    }
}

TEST(Launcher, ChildErrorReachesTheJob) {
    RunControl control;
    try {
        runStudyInChild(mpirun(2), childJob("/nonexistent/gem.asc", "", traceOnly(1000)), control);
        FAIL() << "no error";
    } catch (const Error& e) {
        EXPECT_NE(std::string(e.what()).find("/nonexistent/gem.asc"), std::string::npos) << e.what();
    }
}

TEST(Launcher, CancelEndsTheWholeProcessGroupEvenWhenItIgnoresSigterm) {
    const fs::path dir = fs::temp_directory_path() / ("facetlight-launcher-test-" + std::to_string(getpid()));
    fs::create_directories(dir);
    const fs::path pidFile = dir / "grandchild.pid";
    // The launcher ignores SIGTERM and leaves a grandchild: both must be gone after the cancel.
    const std::string script = "trap '' TERM; sleep 60 & echo $! > " + pidFile.string() +
                               "; echo '{\"phase\":\"tracing\",\"done\":1,\"total\":9}'; wait";
    RunControl control;
    std::thread canceller = cancelWhenTracing(control);
    EXPECT_THROW(runStudyInChild(settingsWith({"sh", "-c", script, "sh"}),
                                 childJob(kMesh, "", traceOnly(1000)), control),
                 Canceled);
    canceller.join();
    const pid_t grandchild = readPid(pidFile);
    ASSERT_GT(grandchild, 0);
    for (int i = 0; i < 200 && running(grandchild); ++i)
        std::this_thread::sleep_for(std::chrono::milliseconds(10));
    EXPECT_FALSE(running(grandchild));
    fs::remove_all(dir);
}

TEST(Launcher, RunsAJobThroughMpirunAndMatchesTheInProcessResult) {
    ASSERT_TRUE(kRootAllowed);
    const StudySettings settings = traceOnly(100'000);
    RunControl control;
    const StudyResult child = runStudyInChild(mpirun(2), childJob(kMesh, "brilliant", settings), control);
    EXPECT_EQ(control.phase(), RunPhase::Done);  // the child's last progress line arrived
    EXPECT_EQ(child.stats["timing"]["ranks"], 2);
    EXPECT_EQ(child.stats["totals"]["photons"], 100'000);
    EXPECT_EQ(child.stats["mesh"]["name"], "brilliant");

    Stone stone = resolveStone(kMesh);
    stone.name = "brilliant";
    RunControl local;
    const StudyResult inProcess = runStudy(stone, settings, local);
    EXPECT_EQ(withoutTiming(child.stats), withoutTiming(inProcess.stats));
    EXPECT_EQ(child.file("stats.csv"), inProcess.file("stats.csv"));
    EXPECT_EQ(child.file("heatmap.png"), inProcess.file("heatmap.png"));
}

TEST(Launcher, CancelsAJobRunningUnderMpirun) {
    LaunchSettings launch = mpirun(2);
    launch.workDir = fs::temp_directory_path() / ("facetlight-cancel-test-" + std::to_string(getpid()));
    fs::create_directories(launch.workDir);
    RunControl control;
    std::thread canceller = cancelWhenTracing(control);
    EXPECT_THROW(runStudyInChild(launch, childJob(kMesh, "", traceOnly(5'000'000'000ULL)), control),
                 Canceled);
    canceller.join();
    EXPECT_GT(control.total(), 0u);  // progress arrived before the cancel
    // The job folder is gone with the job, and no process still runs the job's command line.
    EXPECT_TRUE(fs::is_empty(launch.workDir));
    for (int i = 0; i < 300; ++i) {
        bool left = false;
        for (const auto& entry : fs::directory_iterator("/proc")) {
            std::ifstream cmdline(entry.path() / "cmdline");
            std::string text((std::istreambuf_iterator<char>(cmdline)), {});
            const std::string name = entry.path().filename().string();
            if (text.find(launch.workDir.string()) != std::string::npos && running(std::atoi(name.c_str())))
                left = true;
        }
        if (!left) break;
        ASSERT_LT(i, 299) << "a rank survived the cancel";
        std::this_thread::sleep_for(std::chrono::milliseconds(10));
    }
    fs::remove_all(launch.workDir);
}
