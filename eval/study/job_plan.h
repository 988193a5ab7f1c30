// What a study would do, before it does it (study --plan): each job in the order the runner
// considers them, whether it is complete, can continue from a checkpoint or is still to run, its
// program, its estimated work and the jobs it waits for; then the totals. Reads only the jobs'
// markers: nothing is created, run or checked.
#pragma once

#include <string>
#include <vector>

#include "eval/study/job_graph.h"

namespace colav {

/// The plan of `jobs` as text, one line per job and a closing line of totals.
std::string DescribeJobPlan(const std::vector<StudyJob>& jobs);

}  // namespace colav
