#pragma once
// A study: one scene (or family of scenes) and the question it answers, run with its
// settings, giving rows for results.csv, charts, and a section of results.md.

#include <filesystem>
#include <functional>
#include <string>
#include <vector>

#include "charts.h"
#include "row.h"

namespace bench {

struct StudyContext {
    bool quick = false;                // seconds, not minutes: fewer settings, shorter runs
    int repeats = 3;                   // timed runs per setting (the cost is their median)
    std::filesystem::path scenes_dir;  // the shipped scene files
};

struct Figure {
    std::string file;  // "scale.png"
    Chart chart;
};

struct StudyResult {
    std::vector<Row> rows;
    std::vector<Figure> figures;
    std::string markdown;                  // the study's section of results.md, from its "## " heading
    std::vector<std::string> key_figures;  // one-line findings for the top of results.md
};

struct Study {
    std::string name;  // what --only selects
    std::function<StudyResult(const StudyContext&)> run;
};

// Every study, in the order the bench runs them.
std::vector<Study> all_studies();

// The studies (each in its own file).
StudyResult stacking_study(const StudyContext& context, int rows);
StudyResult rain_study(const StudyContext& context, int shapes);
StudyResult box2d_target_study(const StudyContext& context);
StudyResult gas_study(const StudyContext& context);
StudyResult trajectory_study(const StudyContext& context);
StudyResult slide_study(const StudyContext& context);
StudyResult heavy_on_light_study(const StudyContext& context);
StudyResult slope_study(const StudyContext& context);
StudyResult tunnelling_study(const StudyContext& context);
StudyResult scale_study(const StudyContext& context);
StudyResult pair_cost_study(const StudyContext& context);
StudyResult speed_study(const StudyContext& context);

}  // namespace bench
