#include "launcher.h"

#include <stdlib.h>

#include <cerrno>
#include <cstring>
#include <fstream>
#include <optional>
#include <sstream>

#include <nlohmann/json.hpp>

#include "study/job_request.h"
#include "study/result_files.h"
#include "util/error.h"

namespace facetlight::server {
namespace fs = std::filesystem;

namespace {

std::string defaultExecutable() {
    std::error_code ec;
    const fs::path self = fs::read_symlink("/proc/self/exe", ec);
    if (ec) throw Error("launcher: cannot find this program's directory to locate facetlight");
    return (self.parent_path() / "facetlight").string();
}

std::optional<std::string> readFile(const fs::path& p) {
    std::ifstream in(p, std::ios::binary);
    if (!in) return std::nullopt;
    std::ostringstream s;
    s << in.rdbuf();
    return s.str();
}

// A fresh, private job folder under `dir`, removed again when the job is over.
class JobFolder {
  public:
    explicit JobFolder(const fs::path& dir) {
        std::string pattern =
            ((dir.empty() ? fs::temp_directory_path() : dir) / "facetlight-job-XXXXXX").string();
        if (!mkdtemp(pattern.data()))
            throw Error("launcher: cannot create a job folder in " +
                        fs::path(pattern).parent_path().string() + ": " + std::strerror(errno));
        path_ = pattern;
    }
    ~JobFolder() {
        std::error_code ec;
        fs::remove_all(path_, ec);
    }
    const fs::path& path() const { return path_; }

  private:
    fs::path path_;
};

}  // namespace

std::vector<std::string> splitWords(std::string_view text) {
    std::vector<std::string> words;
    std::string word;
    bool inWord = false;
    char quote = 0;
    for (size_t i = 0; i < text.size(); ++i) {
        const char c = text[i];
        if (quote) {
            if (c == quote) {
                quote = 0;
            } else if (c == '\\' && quote == '"' && i + 1 < text.size()) {
                word.push_back(text[++i]);
            } else {
                word.push_back(c);
            }
        } else if (c == '\'' || c == '"') {
            quote = c;
            inWord = true;
        } else if (c == '\\' && i + 1 < text.size()) {
            word.push_back(text[++i]);
            inWord = true;
        } else if (c == ' ' || c == '\t' || c == '\n') {
            if (inWord) words.push_back(std::move(word));
            word.clear();
            inWord = false;
        } else {
            word.push_back(c);
            inWord = true;
        }
    }
    if (quote) throw Error(std::string("launcher: unclosed ") + quote + " in '" + std::string(text) + "'");
    if (inWord) words.push_back(std::move(word));
    return words;
}

bool useLauncher(const LaunchSettings& launch, const StudySettings& settings) {
    uint64_t photons = settings.trace.photons + (settings.render ? settings.render->mapPhotons : 0);
    if (settings.sweep)
        for (const SweepAxis& axis : settings.sweep->axes) photons *= axis.size();  // every point's
    return photons >= launch.minPhotons;
}

bool applyProgressLine(std::string_view line, RunControl& control) {
    if (line.empty() || line.front() != '{') return false;
    const nlohmann::json j = nlohmann::json::parse(line, nullptr, false);
    if (!j.is_object() || !j.contains("phase") || !j["phase"].is_string()) return false;
    const std::optional<RunPhase> phase = runPhaseNamed(j["phase"].get<std::string>());
    if (!phase) return false;
    const auto count = [&](const char* key) {
        const auto it = j.find(key);
        return it != j.end() && it->is_number_unsigned() ? it->get<uint64_t>() : uint64_t(0);
    };
    control.show(*phase, count("done"), count("total"));
    return true;
}

StudyResult runStudyInChild(const LaunchSettings& launch, const JobRequest& spec, RunControl& control) {
    const JobFolder folder(launch.workDir);
    const fs::path jobFile = folder.path() / "job.json";
    {
        // The child is another process: it gets the job as the canonical JSON written from the typed spec,
        // and reading that file is its one parse (cli/study_command.cpp).
        std::ofstream out(jobFile);
        out << toJson(spec).dump(2);
        if (!(out << std::flush)) throw Error("launcher: cannot write " + jobFile.string());
    }

    std::vector<std::string> argv = launch.launcher;
    argv.push_back(launch.executable.empty() ? defaultExecutable() : launch.executable);
    for (const char* a : {"study", "--progress-json", "--job"}) argv.emplace_back(a);
    argv.push_back(jobFile.string());
    argv.emplace_back("--out");
    argv.push_back(folder.path().string());

    const ChildExit exit = runChild(
        argv, [&](std::string_view line) { return applyProgressLine(line, control); }, control,
        launch.cancelGrace);
    if (exit.cancelled) throw Canceled();
    const std::string command = argv.front();
    if (exit.signal != 0)
        throw Error("launcher: '" + command + "' was killed by signal " + std::to_string(exit.signal) + ": " +
                    exit.tail);
    if (exit.exitCode != 0)
        throw Error("launcher: '" + command + "' failed with exit code " + std::to_string(exit.exitCode) +
                    ": " + exit.tail);

    // The file a study writes last.
    if (!fs::exists(folder.path() / (spec.settings.sweep ? "sweep.json" : "stats.json")))
        throw Error("launcher: the job left no results in " + folder.path().string() +
                    " (is it a directory every node shares?): " + exit.tail);
    StudyResult result;
    for (const ResultFile& f : kResultFiles)
        if (auto bytes = readFile(folder.path() / f.name)) result.load(f, std::move(*bytes));
    return result;
}

}  // namespace facetlight::server
