#include "bench_run.h"

#include <algorithm>
#include <chrono>
#include <fstream>
#include <ostream>
#include <stdexcept>

#include "box2d_world.h"
#include "output_folder.h"
#include "png_io.h"
#include "report.h"
#include "scene_maker.h"
#include "scene_json.h"
#include "study.h"

namespace bench {
namespace {

namespace fs = std::filesystem;

double seconds_since(std::chrono::steady_clock::time_point start) {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

void write_text(const fs::path& file, const std::string& text) {
    std::ofstream stream(file, std::ios::binary);
    stream << text;
    if (!stream.flush()) throw browser::FileError("cannot write " + file.filename().string());
}

std::vector<Study> chosen(const std::vector<std::string>& only) {
    std::vector<Study> studies = all_studies();
    if (!only.empty()) {
        std::erase_if(studies,
                      [&](const Study& s) { return std::find(only.begin(), only.end(), s.name) == only.end(); });
    }
    return studies;
}

}  // namespace

int run_bench(const BenchOptions& options, std::ostream& out, std::ostream& err) {
    const auto start = std::chrono::steady_clock::now();
    const fs::path target = browser::OutputFolder::normalized(options.out_dir);
    try {
        // Made first, so that a folder that may not be replaced stops the run before
        // minutes of measuring.
        browser::OutputFolder folder(target);
        if (!box2d_available()) out << kNoBox2d << '\n';

        const StudyContext context{.quick = options.quick, .repeats = options.repeats, .scenes_dir = BENCH_SCENES_DIR};
        const std::vector<Study> studies = chosen(options.only);
        std::vector<StudyResult> results;
        std::vector<Row> rows;
        for (std::size_t i = 0; i < studies.size(); ++i) {
            const auto study_start = std::chrono::steady_clock::now();
            results.push_back(studies[i].run(context));
            const StudyResult& result = results.back();
            rows.insert(rows.end(), result.rows.begin(), result.rows.end());
            for (const Figure& figure : result.figures) write_chart(figure.chart, folder.staging() / figure.file);
            out << "[" << i + 1 << "/" << studies.size() << "] " << studies[i].name << ": " << result.rows.size()
                << (result.rows.size() == 1 ? " setting" : " settings") << " in " << seconds_since(study_start) << " s"
                << std::endl;
        }
        write_text(folder.staging() / kResultsCsv, results_csv(rows));
        const RunFacts facts{.quick = options.quick,
                             .repeats = options.repeats,
                             .seconds = seconds_since(start),
                             .box2d = box2d_available()};
        write_text(folder.staging() / "results.md", results_markdown(facts, results));
        folder.commit();
        out << "wrote " << rows.size() << " rows to " << (target / kResultsCsv).string()
            << ", results.md and the charts (" << seconds_since(start) << " s)\n";
        return 0;
    } catch (const browser::FileError& error) {
        err << "bench: cannot write results to \"" << target.string() << "\": " << error.what() << '\n';
    } catch (const fs::filesystem_error& error) {
        err << "bench: cannot write results to \"" << target.string() << "\": " << error.code().message() << '\n';
    } catch (const std::exception& error) {  // a scene that does not load, a study that fails
        err << "bench: " << error.what() << '\n';
    }
    return 1;
}

int write_scene_files(const fs::path& dir, std::ostream& out, std::ostream& err) {
    try {
        fs::create_directories(dir);
        const std::vector<scenes::NamedScene> all = scenes::shipped();
        for (const scenes::NamedScene& named : all) write_scene(dir / (named.name + ".json"), named.scene);
        out << "wrote " << all.size() << " scene files to " << dir.string() << '\n';
        return 0;
    } catch (const browser::FileError& error) {
        err << "bench: " << error.what() << '\n';
    } catch (const fs::filesystem_error& error) {
        err << "bench: cannot write scene files to \"" << dir.string() << "\": " << error.code().message() << '\n';
    }
    return 1;
}

}  // namespace bench
