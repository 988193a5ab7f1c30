#include "eval/study/study_spec.h"

#include <fmt/format.h>
#include <yaml-cpp/yaml.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <regex>
#include <set>

#include "eval/study/study_metrics.h"
#include "src/error.h"
#include "src/yaml_file.h"

namespace colav {
namespace {

constexpr std::int64_t kMaxPpoSteps = 1'000'000'000;
constexpr double kSensorRangeM = 150.0;  // env/range_finder.h (the study links no simulator)

// The number `text` spells, NaN unless all of it is one.
double ParseNumber(const std::string& text) {
  try {
    std::size_t used = 0;
    const double value = std::stod(text, &used);
    return used == text.size() ? value : NAN;
  } catch (const std::exception&) {
    return NAN;
  }
}

// Errors name the file and the key path ("studies/x.yaml: ppo.configs.best.locked: ...").
class Reader {
 public:
  explicit Reader(std::filesystem::path path) : path_(std::move(path)) {}

  [[noreturn]] void Fail(const std::string& key, const std::string& problem) const {
    throw UserError(path_.string() + ": " + key + ": " + problem);
  }

  // `allowed` empty: any key (a mapping of names to entries).
  void RequireMap(const YAML::Node& node, const std::string& key,
                  const std::set<std::string>& allowed) const {
    if (!node.IsMap()) Fail(key, "expects a mapping");
    for (const auto& item : node) {
      const std::string name = item.first.as<std::string>();
      if (!allowed.empty() && allowed.count(name) == 0) {
        Fail(key.empty() ? name : fmt::format("{}.{}", key, name), "unknown key");
      }
    }
  }

  std::string Name(const YAML::Node& node, const std::string& key) const {
    std::string name = String(node, key);
    static const std::regex kSafe("[A-Za-z0-9][A-Za-z0-9_.-]*");
    if (!std::regex_match(name, kSafe)) Fail(key, "'" + name + "' is not a safe folder name");
    return name;
  }

  std::string String(const YAML::Node& node, const std::string& key) const {
    if (!node.IsScalar()) Fail(key, "expects a text value");
    return node.Scalar();
  }

  std::string Choice(const YAML::Node& node, const std::string& key,
                     const std::vector<std::string>& choices) const {
    std::string value = String(node, key);
    if (std::find(choices.begin(), choices.end(), value) == choices.end()) {
      Fail(key, "'" + value + "' is not one of the allowed values");
    }
    return value;
  }

  std::int64_t Integer(const YAML::Node& node, const std::string& key, std::int64_t min,
                       std::int64_t max) const {
    const std::string text = String(node, key);
    const double value = ParseNumber(text);
    if (!std::isfinite(value) || std::floor(value) != value || value < static_cast<double>(min) ||
        value > static_cast<double>(max)) {
      Fail(key, "expects a whole number in [" + std::to_string(min) + ", " + std::to_string(max) +
                    "], got '" + text + "'");
    }
    return static_cast<std::int64_t>(value);
  }

  // A number strictly between `low` and `high`.
  double Number(const YAML::Node& node, const std::string& key, double low, double high) const {
    const std::string text = String(node, key);
    const double value = ParseNumber(text);
    if (!(value > low && value < high)) {
      Fail(key, fmt::format("expects a number in ({}, {}), got '{}'", low, high, text));
    }
    return value;
  }

  bool Bool(const YAML::Node& node, const std::string& key) const {
    const std::string text = String(node, key);
    if (text != "true" && text != "false") Fail(key, "expects true or false, got '" + text + "'");
    return text == "true";
  }

  // A mapping of program configuration keys to values, kept as "key=value" overrides; the
  // program checks the keys and values (before the study starts: CheckJobConfigurations,
  // job_runner.h).
  Overrides OverridesOf(const YAML::Node& node, const std::string& key) const {
    Overrides overrides;
    if (!node) return overrides;
    if (!node.IsMap()) Fail(key, "expects a mapping of configuration keys to values");
    for (const auto& item : node) {
      const std::string name = item.first.as<std::string>();
      const std::string value = String(item.second, fmt::format("{}.{}", key, name));
      overrides.push_back(fmt::format("{}={}", name, value));
    }
    return overrides;
  }

  const std::filesystem::path& path() const { return path_; }

 private:
  std::filesystem::path path_;
};

std::vector<VaeSpec> ReadVaes(const Reader& reader, const YAML::Node& node) {
  std::vector<VaeSpec> vaes;
  if (!node) return vaes;
  reader.RequireMap(node, "vaes", {});
  for (const auto& item : node) {
    VaeSpec vae;
    const std::string key = "vaes." + item.first.as<std::string>();
    vae.name = reader.Name(item.first, key);
    reader.RequireMap(item.second, key, {"model", "seeds", "set"});
    if (item.second["model"]) {
      vae.model = reader.Choice(item.second["model"], key + ".model", {"shallow", "deep"});
    }
    if (item.second["seeds"]) {
      vae.seeds = static_cast<int>(reader.Integer(item.second["seeds"], key + ".seeds", 1, 1000));
    }
    vae.overrides = reader.OverridesOf(item.second["set"], key + ".set");
    vaes.push_back(vae);
  }
  return vaes;
}

PpoConfigSpec ReadPpoConfig(const Reader& reader, const YAML::Node& name, const YAML::Node& node,
                            const std::vector<VaeSpec>& vaes) {
  PpoConfigSpec config;
  const std::string key = "ppo.configs." + name.as<std::string>();
  config.name = reader.Name(name, key);
  reader.RequireMap(node, key, {"extractor", "vae", "locked", "set", "steps", "compare_to"});
  if (node["extractor"]) {
    config.extractor = reader.Choice(node["extractor"], key + ".extractor",
                                     {"baseline", "vae-shallow", "vae-deep"});
  }
  if (node["locked"]) config.locked = reader.Bool(node["locked"], key + ".locked");
  config.overrides = reader.OverridesOf(node["set"], key + ".set");
  if (node["steps"]) config.steps = reader.Integer(node["steps"], key + ".steps", 1, kMaxPpoSteps);
  if (node["compare_to"]) config.compare_to = reader.Name(node["compare_to"], key + ".compare_to");
  if (config.extractor == "baseline") {
    if (node["vae"]) reader.Fail(key + ".vae", "the baseline extractor uses no VAE");
    return config;
  }
  if (!node["vae"]) reader.Fail(key + ".vae", "missing: " + config.extractor + " needs a VAE");
  config.vae = reader.String(node["vae"], key + ".vae");
  const auto vae = std::find_if(vaes.begin(), vaes.end(),
                                [&](const VaeSpec& v) { return v.name == config.vae; });
  if (vae == vaes.end()) reader.Fail(key + ".vae", "no VAE named '" + config.vae + "' in vaes");
  if ("vae-" + vae->model != config.extractor) {
    reader.Fail(key + ".vae", "VAE '" + config.vae + "' is " + vae->model + ", the extractor " +
                                  config.extractor);
  }
  return config;
}

void ReadPpo(const Reader& reader, const YAML::Node& node, StudySpec& spec) {
  if (!node) reader.Fail("ppo", "missing: a study trains at least one PPO configuration");
  reader.RequireMap(node, "ppo", {"seeds", "steps", "set", "configs"});
  if (node["seeds"]) {
    spec.ppo_seeds = static_cast<int>(reader.Integer(node["seeds"], "ppo.seeds", 1, 1000));
  }
  if (node["steps"]) {
    spec.ppo_steps = reader.Integer(node["steps"], "ppo.steps", 1, kMaxPpoSteps);
  }
  spec.ppo_overrides = reader.OverridesOf(node["set"], "ppo.set");
  if (!node["configs"] || node["configs"].size() == 0) {
    reader.Fail("ppo.configs", "missing: name at least one PPO configuration");
  }
  reader.RequireMap(node["configs"], "ppo.configs", {});
  for (const auto& item : node["configs"]) {
    spec.ppo_configs.push_back(ReadPpoConfig(reader, item.first, item.second, spec.vaes));
  }
}

// How many times each configuration is listed in `members`.
std::map<std::string, int> Multiplicities(const std::vector<std::string>& members) {
  std::map<std::string, int> times;
  for (const std::string& member : members) ++times[member];
  return times;
}

EnsembleSpec ReadEnsemble(const Reader& reader, const YAML::Node& name, const YAML::Node& node,
                          const StudySpec& spec) {
  EnsembleSpec ensemble;
  const std::string key = "ensembles." + name.as<std::string>();
  ensemble.name = reader.Name(name, key);
  const auto is_config = [&](const std::string& config) {
    return std::any_of(spec.ppo_configs.begin(), spec.ppo_configs.end(),
                       [&](const PpoConfigSpec& c) { return c.name == config; });
  };
  if (is_config(ensemble.name)) reader.Fail(key, "is also the name of a PPO configuration");
  reader.RequireMap(node, key,
                    {"members", "count", "near_within_m", "stall_pace_mps", "stall_steps"});
  const YAML::Node members = node["members"];
  if (!members || !members.IsSequence() || members.size() < 2) {
    reader.Fail(key + ".members", "expects a list of two or more PPO configurations");
  }
  for (std::size_t i = 0; i < members.size(); ++i) {
    const std::string member_key = fmt::format("{}.members[{}]", key, i);
    ensemble.members.push_back(reader.String(members[i], member_key));
    if (!is_config(ensemble.members.back())) {
      reader.Fail(member_key, "'" + ensemble.members.back() + "' is not a PPO configuration");
    }
  }
  const int most = ensemble.MaxCount(spec.ppo_seeds);
  if (most == 0) {
    reader.Fail(key + ".members", fmt::format("lists a configuration more often than its {} "
                                              "seed(s)",
                                              spec.ppo_seeds));
  }
  if (node["near_within_m"]) {
    if (!RangeRuleFits(ensemble.members.size(), node["stall_pace_mps"].IsDefined())) {
      reader.Fail(key + ".near_within_m",
                  "takes two members (the one near obstacles, the other), or more with "
                  "stall_pace_mps (the later ones relieve at the second stall and after)");
    }
    ensemble.near_within_m =
        reader.Number(node["near_within_m"], key + ".near_within_m", 0.0, kSensorRangeM);
  }
  if (node["stall_pace_mps"]) {
    StallRule stall;
    stall.pace_mps =
        reader.Number(node["stall_pace_mps"], key + ".stall_pace_mps", 0.0, kStallPaceStartMps);
    if (node["stall_steps"]) {
      stall.steps = static_cast<int>(
          reader.Integer(node["stall_steps"], key + ".stall_steps", 1, kMaxStallSteps));
    }
    ensemble.stall = stall;
  } else if (node["stall_steps"]) {
    reader.Fail(key + ".stall_steps", "needs stall_pace_mps");
  }
  ensemble.count = most;
  if (node["count"]) {
    ensemble.count = static_cast<int>(reader.Integer(node["count"], key + ".count", 1, most));
    ensemble.count_given = true;
  }
  return ensemble;
}

// The entries of the section `section` (a mapping of names to entries; absent: none), each read
// by `read_entry(reader, name, entry, spec)`.
template <typename ReadEntry>
auto ReadNamedEntries(const Reader& reader, const YAML::Node& node, const std::string& section,
                      const StudySpec& spec, ReadEntry read_entry) {
  std::vector<decltype(read_entry(reader, node, node, spec))> entries;
  if (!node) return entries;
  reader.RequireMap(node, section, {});
  for (const auto& item : node) {
    entries.push_back(read_entry(reader, item.first, item.second, spec));
  }
  return entries;
}

// distill_policy's options the study sets itself (StudentSpec).
const std::set<std::string> kStudyStudentOptions = {"out", "seed", "resume", "print-config"};

// The memory size `config`'s runs are trained with: the last policy.recurrent_size of the
// study-wide then the configuration's overrides (0, train_ppo's default, when none sets it).
double RecurrentSize(const StudySpec& spec, const PpoConfigSpec& config) {
  return LastSetting({&spec.ppo_overrides, &config.overrides}, "policy.recurrent_size", 0.0);
}

// distill_policy's options as "--name value" pairs; the script checks the names and values
// (before the study starts: CheckJobConfigurations, job_runner.h).
std::vector<std::string> StudentOptions(const Reader& reader, const YAML::Node& node,
                                        const std::string& key) {
  std::vector<std::string> options;
  if (!node) return options;
  if (!node.IsMap()) reader.Fail(key, "expects a mapping of distill_policy options to values");
  static const std::regex kOption("[a-z][a-z0-9-]*");
  for (const auto& item : node) {
    const std::string name = item.first.as<std::string>();
    const std::string option_key = fmt::format("{}.{}", key, name);
    if (!std::regex_match(name, kOption)) {
      reader.Fail(option_key, "expects an option's name without its dashes, e.g. traps");
    }
    if (kStudyStudentOptions.count(name) > 0) reader.Fail(option_key, "is set by the study");
    options.push_back("--" + name);
    options.push_back(reader.String(item.second, option_key));
  }
  return options;
}

StudentSpec ReadStudent(const Reader& reader, const YAML::Node& name, const YAML::Node& node,
                        const StudySpec& spec) {
  StudentSpec student;
  const std::string key = "students." + name.as<std::string>();
  student.name = reader.Name(name, key);
  if (spec.FindConfig(student.name) || spec.FindEnsemble(student.name)) {
    reader.Fail(key, "is also the name of a PPO configuration or ensemble");
  }
  reader.RequireMap(node, key, {"teacher", "start", "options", "compare_to"});
  for (const char* required : {"teacher", "start"}) {
    if (!node[required]) reader.Fail(key + "." + required, "missing");
  }
  student.teacher = reader.String(node["teacher"], key + ".teacher");
  student.count = spec.TeacherSeeds(student.teacher);
  if (student.count == 0) {
    reader.Fail(key + ".teacher",
                "'" + student.teacher + "' is not an ensemble or PPO configuration of the study");
  }
  student.start = reader.String(node["start"], key + ".start");
  const PpoConfigSpec* start = spec.FindConfig(student.start);
  if (!start) reader.Fail(key + ".start", "'" + student.start + "' is not a PPO configuration");
  if (!(RecurrentSize(spec, *start) > 0)) {
    reader.Fail(key + ".start", "'" + student.start +
                                    "' is not recurrent: give it policy.recurrent_size in its set");
  }
  student.options = StudentOptions(reader, node["options"], key + ".options");
  if (node["compare_to"]) student.compare_to = reader.Name(node["compare_to"], key + ".compare_to");
  return student;
}

// train_ppo's keys a fine-tune's set may not give: the study sets them (FineTuneSpec).
const std::set<std::string> kStudyFineTuneKeys = {"policy.init"};

FineTuneSpec ReadFineTune(const Reader& reader, const YAML::Node& name, const YAML::Node& node,
                          const StudySpec& spec) {
  FineTuneSpec fine_tune;
  const std::string key = "fine_tunes." + name.as<std::string>();
  fine_tune.name = reader.Name(name, key);
  if (spec.FindConfig(fine_tune.name) || spec.FindEnsemble(fine_tune.name) ||
      spec.FindStudent(fine_tune.name)) {
    reader.Fail(key, "is also the name of a PPO configuration, ensemble or student");
  }
  reader.RequireMap(node, key, {"student", "steps", "set", "compare_to"});
  if (!node["student"]) reader.Fail(key + ".student", "missing");
  fine_tune.student = reader.String(node["student"], key + ".student");
  const StudentSpec* student = spec.FindStudent(fine_tune.student);
  if (!student) {
    reader.Fail(key + ".student", "'" + fine_tune.student + "' is not a student of the study");
  }
  fine_tune.count = student->count;
  if (node["steps"]) {
    fine_tune.steps = reader.Integer(node["steps"], key + ".steps", 1, kMaxPpoSteps);
  }
  fine_tune.overrides = reader.OverridesOf(node["set"], key + ".set");
  for (const std::string& assignment : fine_tune.overrides) {
    const std::string set_key = assignment.substr(0, assignment.find('='));
    if (kStudyFineTuneKeys.count(set_key) > 0) {
      reader.Fail(fmt::format("{}.set.{}", key, set_key), "is set by the study");
    }
  }
  if (node["compare_to"]) {
    fine_tune.compare_to = reader.Name(node["compare_to"], key + ".compare_to");
  }
  return fine_tune;
}

// A file named relative to the study file's folder; it must exist.
std::filesystem::path ExistingFile(const Reader& reader, const YAML::Node& node,
                                   const std::string& key) {
  std::filesystem::path file = reader.String(node, key);
  if (file.is_relative()) file = reader.path().parent_path() / file;
  if (!std::filesystem::is_regular_file(file)) reader.Fail(key, file.string() + ": no such file");
  return file;
}

// The largest master seed a study file may give: 2^53, the largest integer its numbers spell
// exactly.
constexpr std::int64_t kLargestSeed = 9'007'199'254'740'992;

// evaluation.goal: metric name -> bound, each a metric of the report, a rate's or the progress's
// bound within [0, 100] %.
std::map<std::string, double> ReadGoal(const Reader& reader, const YAML::Node& node) {
  std::map<std::string, double> goal;
  if (!node) return goal;
  if (!node.IsMap() || node.size() == 0) {
    reader.Fail("evaluation.goal",
                "expects a mapping of metrics to bounds, e.g. {progress: 97, collision: 3}");
  }
  for (const auto& item : node) {
    const std::string name = item.first.as<std::string>();
    const std::string key = "evaluation.goal." + name;
    const StudyMetric* metric = FindStudyMetric(name);
    if (!metric) {
      std::vector<std::string> names;
      for (const StudyMetric& m : StudyMetrics()) names.push_back(m.name);
      reader.Fail(key, fmt::format("not a metric of the report ({})", fmt::join(names, ", ")));
    }
    const double infinity = std::numeric_limits<double>::infinity();
    const double bound = reader.Number(item.second, key, -infinity, infinity);
    if (metric->bounded() && (bound < 0.0 || bound > metric->scale)) {
      reader.Fail(key, fmt::format("expects a bound in [0, {}] %, got {}", metric->scale, bound));
    }
    goal[name] = bound;
  }
  return goal;
}

EvaluationSpec ReadEvaluation(const Reader& reader, const YAML::Node& node) {
  EvaluationSpec evaluation;
  if (!node) return evaluation;
  reader.RequireMap(node, "evaluation",
                    {"episodes", "seed", "paper_episodes", "validation_episodes", "validation_seed",
                     "goal", "reference_agents", "paper_results", "compare_to"});
  if (node["episodes"]) {
    evaluation.episodes =
        static_cast<int>(reader.Integer(node["episodes"], "evaluation.episodes", 1, 100000));
  }
  if (node["seed"]) {
    evaluation.seed = static_cast<std::uint64_t>(
        reader.Integer(node["seed"], "evaluation.seed", 0, kLargestSeed));
  }
  if (node["paper_episodes"]) {
    evaluation.paper_episodes = static_cast<int>(
        reader.Integer(node["paper_episodes"], "evaluation.paper_episodes", 0, 100000));
  }
  if (node["validation_episodes"]) {
    evaluation.validation_episodes = static_cast<int>(
        reader.Integer(node["validation_episodes"], "evaluation.validation_episodes", 0, 100000));
  }
  if (node["validation_seed"]) {
    evaluation.validation_seed = static_cast<std::uint64_t>(
        reader.Integer(node["validation_seed"], "evaluation.validation_seed", 0, kLargestSeed));
  }
  if (evaluation.validation_episodes > 0 && evaluation.validation_seed == evaluation.seed) {
    reader.Fail("evaluation.validation_seed",
                "equals evaluation.seed: the validation scenarios would be the test's");
  }
  evaluation.goal = ReadGoal(reader, node["goal"]);
  if (node["paper_results"]) {
    evaluation.paper_results =
        ExistingFile(reader, node["paper_results"], "evaluation.paper_results");
  }
  if (node["compare_to"]) {
    evaluation.compare_to = reader.Name(node["compare_to"], "evaluation.compare_to");
  }
  if (const YAML::Node agents = node["reference_agents"]) {
    if (!agents.IsSequence()) reader.Fail("evaluation.reference_agents", "expects a list of files");
    for (std::size_t i = 0; i < agents.size(); ++i) {
      const std::string key = "evaluation.reference_agents[" + std::to_string(i) + "]";
      evaluation.reference_agents.push_back(ExistingFile(reader, agents[i], key));
    }
  }
  return evaluation;
}

}  // namespace

double LastSetting(std::initializer_list<const Overrides*> chain, const std::string& key,
                   double fallback) {
  const std::string prefix = key + "=";
  double value = fallback;
  for (const Overrides* overrides : chain) {
    for (const std::string& assignment : *overrides) {
      if (assignment.rfind(prefix, 0) == 0) value = ParseNumber(assignment.substr(prefix.size()));
    }
  }
  return value;
}

int EnsembleSpec::MemberSeed(std::size_t member, int k) const {
  const auto earlier =
      std::count(members.begin(), members.begin() + static_cast<long>(member), members[member]);
  return k + static_cast<int>(earlier) * count;
}

int EnsembleSpec::MaxCount(int seeds) const {
  int most = seeds;
  for (const auto& [config, times] : Multiplicities(members)) most = std::min(most, seeds / times);
  return most;
}

bool StudySpec::HasModel(const std::string& name) const {
  const std::vector<SeededModel> models = SeededModels();
  return std::any_of(models.begin(), models.end(),
                     [&](const SeededModel& m) { return m.name == name; });
}

std::vector<SeededModel> StudySpec::SeededModels() const {
  std::vector<SeededModel> models;
  for (const PpoConfigSpec& config : ppo_configs) {
    models.push_back({config.name, ppo_seeds, config.compare_to});
  }
  for (const EnsembleSpec& ensemble : ensembles) models.push_back({ensemble.name, ensemble.count});
  for (const StudentSpec& student : students) {
    models.push_back({student.name, student.count, student.compare_to});
  }
  for (const FineTuneSpec& fine_tune : fine_tunes) {
    models.push_back({fine_tune.name, fine_tune.count, fine_tune.compare_to});
  }
  return models;
}

const PpoConfigSpec* StudySpec::FindConfig(const std::string& name) const {
  const auto found = std::find_if(ppo_configs.begin(), ppo_configs.end(),
                                  [&](const PpoConfigSpec& c) { return c.name == name; });
  return found == ppo_configs.end() ? nullptr : &*found;
}

int StudySpec::TeacherSeeds(const std::string& teacher) const {
  if (const EnsembleSpec* ensemble = FindEnsemble(teacher)) return ensemble->count;
  return FindConfig(teacher) ? ppo_seeds : 0;
}

const EnsembleSpec* StudySpec::FindEnsemble(const std::string& name) const {
  const auto found = std::find_if(ensembles.begin(), ensembles.end(),
                                  [&](const EnsembleSpec& e) { return e.name == name; });
  return found == ensembles.end() ? nullptr : &*found;
}

const StudentSpec* StudySpec::FindStudent(const std::string& name) const {
  const auto found = std::find_if(students.begin(), students.end(),
                                  [&](const StudentSpec& s) { return s.name == name; });
  return found == students.end() ? nullptr : &*found;
}

int StudySpec::StartSeed(const StudentSpec& student, int k) const {
  if (const EnsembleSpec* ensemble = FindEnsemble(student.teacher)) {
    const auto member =
        std::find(ensemble->members.begin(), ensemble->members.end(), student.start);
    if (member != ensemble->members.end()) {
      return ensemble->MemberSeed(static_cast<std::size_t>(member - ensemble->members.begin()), k);
    }
  }
  return k;
}

StudySpec LoadStudySpec(const std::filesystem::path& path) {
  const YAML::Node root = LoadYamlFile(path);
  const Reader reader(path);
  reader.RequireMap(root, "",
                    {"name", "dataset", "vaes", "ppo", "ensembles", "students", "fine_tunes",
                     "evaluation", "vae_figures"});
  StudySpec spec;
  spec.name = root["name"] ? reader.Name(root["name"], "name") : path.stem().string();
  spec.dataset_overrides = reader.OverridesOf(root["dataset"], "dataset");
  spec.vaes = ReadVaes(reader, root["vaes"]);
  ReadPpo(reader, root["ppo"], spec);
  spec.ensembles = ReadNamedEntries(reader, root["ensembles"], "ensembles", spec, ReadEnsemble);
  spec.students = ReadNamedEntries(reader, root["students"], "students", spec, ReadStudent);
  spec.fine_tunes = ReadNamedEntries(reader, root["fine_tunes"], "fine_tunes", spec, ReadFineTune);
  spec.evaluation = ReadEvaluation(reader, root["evaluation"]);
  if (root["vae_figures"]) spec.vae_figures = reader.Bool(root["vae_figures"], "vae_figures");
  const auto check_compared_with = [&](const std::string& name, const std::string& key) {
    if (!spec.HasModel(name)) {
      reader.Fail(key, "'" + name +
                           "' is not a PPO configuration, ensemble, student or fine-tune of the "
                           "study");
    }
  };
  if (root["evaluation"] && root["evaluation"]["compare_to"]) {
    check_compared_with(spec.evaluation.compare_to, "evaluation.compare_to");
  }
  // A model's own compare_to (at `section`.<name>.compare_to) names another model of the study.
  const auto check_own_compare_to = [&](const std::string& section, const std::string& name,
                                        const std::string& compare_to, const std::string& kind) {
    if (compare_to.empty()) return;
    const std::string key = section + "." + name + ".compare_to";
    if (compare_to == name) reader.Fail(key, "a " + kind + " is not compared with itself");
    check_compared_with(compare_to, key);
  };
  for (const PpoConfigSpec& config : spec.ppo_configs) {
    check_own_compare_to("ppo.configs", config.name, config.compare_to, "configuration");
  }
  for (const StudentSpec& student : spec.students) {
    check_own_compare_to("students", student.name, student.compare_to, "student");
  }
  for (const FineTuneSpec& fine_tune : spec.fine_tunes) {
    check_own_compare_to("fine_tunes", fine_tune.name, fine_tune.compare_to, "fine-tune");
  }
  return spec;
}

namespace {

// The students whose teacher and start the (restricted) study still has, one per teacher seed,
// and the fine-tunes of the students kept, one per student.
void KeepTaughtStudents(StudySpec& spec) {
  std::vector<StudentSpec> kept;
  for (StudentSpec student : spec.students) {
    student.count = spec.TeacherSeeds(student.teacher);
    if (student.count > 0 && spec.FindConfig(student.start)) kept.push_back(student);
  }
  spec.students = kept;
  std::vector<FineTuneSpec> kept_fine_tunes;
  for (FineTuneSpec fine_tune : spec.fine_tunes) {
    if (const StudentSpec* student = spec.FindStudent(fine_tune.student)) {
      fine_tune.count = student->count;
      kept_fine_tunes.push_back(fine_tune);
    }
  }
  spec.fine_tunes = kept_fine_tunes;
}

// Whether `names` holds `name`.
bool Holds(const std::set<std::string>& names, const std::string& name) {
  return names.count(name) > 0;
}

// The first of `names` that is no model of `spec`, if any.
std::optional<std::string> FirstMissingModel(const StudySpec& spec,
                                             const std::vector<std::string>& names) {
  const auto missing = std::find_if(names.begin(), names.end(),
                                    [&](const std::string& name) { return !spec.HasModel(name); });
  return missing == names.end() ? std::nullopt : std::optional<std::string>(*missing);
}

// The models `only` names and the kinds built from them alone: an ensemble all of whose members
// it holds, a student whose teacher and start it holds, a fine-tune of a student it holds.
std::set<std::string> NamedAndBuiltFrom(const StudySpec& spec,
                                        const std::vector<std::string>& only) {
  std::set<std::string> kept(only.begin(), only.end());
  for (const EnsembleSpec& ensemble : spec.ensembles) {
    if (std::all_of(ensemble.members.begin(), ensemble.members.end(),
                    [&](const std::string& member) { return Holds(kept, member); })) {
      kept.insert(ensemble.name);
    }
  }
  for (const StudentSpec& student : spec.students) {
    if (Holds(kept, student.teacher) && Holds(kept, student.start)) kept.insert(student.name);
  }
  for (const FineTuneSpec& fine_tune : spec.fine_tunes) {
    if (Holds(kept, fine_tune.student)) kept.insert(fine_tune.name);
  }
  return kept;
}

// `kept` with what its models are built from: a fine-tune's student, a student's teacher and
// start, an ensemble's members (each kind is built only from kinds listed before it).
void AddWhatTheyNeed(const StudySpec& spec, std::set<std::string>& kept) {
  for (const FineTuneSpec& fine_tune : spec.fine_tunes) {
    if (Holds(kept, fine_tune.name)) kept.insert(fine_tune.student);
  }
  for (const StudentSpec& student : spec.students) {
    if (Holds(kept, student.name)) kept.insert({student.teacher, student.start});
  }
  for (const EnsembleSpec& ensemble : spec.ensembles) {
    if (Holds(kept, ensemble.name)) kept.insert(ensemble.members.begin(), ensemble.members.end());
  }
}

template <typename Spec>
void KeepOnly(std::vector<Spec>& specs, const std::set<std::string>& kept) {
  specs.erase(std::remove_if(specs.begin(), specs.end(),
                             [&](const Spec& s) { return !Holds(kept, s.name); }),
              specs.end());
}

}  // namespace

StudySpec SelectModels(StudySpec spec, const std::vector<std::string>& only, int seeds) {
  if (const auto unknown = FirstMissingModel(spec, only)) {
    throw UserError("--only " + *unknown +
                    ": the study has no PPO configuration, ensemble, student or fine-tune of "
                    "that name");
  }
  if (seeds > 0) {
    spec.ppo_seeds = seeds;
    for (EnsembleSpec& ensemble : spec.ensembles) {
      const int most = ensemble.MaxCount(seeds);
      ensemble.count = ensemble.count_given ? std::min(ensemble.count, most) : most;
    }
    spec.ensembles.erase(std::remove_if(spec.ensembles.begin(), spec.ensembles.end(),
                                        [](const EnsembleSpec& e) { return e.count == 0; }),
                         spec.ensembles.end());
    KeepTaughtStudents(spec);
  }
  if (only.empty()) return spec;
  if (const auto unseeded = FirstMissingModel(spec, only)) {
    throw UserError("--only " + *unseeded + ": --seeds " + std::to_string(seeds) +
                    " gives none of it (an ensemble it needs takes more training seeds)");
  }
  std::set<std::string> kept = NamedAndBuiltFrom(spec, only);
  AddWhatTheyNeed(spec, kept);
  KeepOnly(spec.ppo_configs, kept);
  KeepOnly(spec.ensembles, kept);
  KeepOnly(spec.students, kept);
  KeepOnly(spec.fine_tunes, kept);
  std::set<std::string> used_vaes;
  for (const PpoConfigSpec& config : spec.ppo_configs) used_vaes.insert(config.vae);
  KeepOnly(spec.vaes, used_vaes);
  spec.vae_figures = false;  // not needed by any model
  return spec;
}

}  // namespace colav
