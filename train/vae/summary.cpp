#include "train/vae/summary.h"

#include <sstream>

#include "src/atomic_file.h"
#include "src/error.h"
#include "src/progress.h"
#include "src/statistics.h"

namespace colav {
namespace {

std::vector<double> Collect(const std::vector<SeedResult>& results,
                            double (*field)(const SeedResult&)) {
  std::vector<double> values;
  values.reserve(results.size());
  for (const SeedResult& result : results) values.push_back(field(result));
  return values;
}

std::string SummaryMarkdown(const VaeTrainingOptions& options,
                            const std::vector<SeedResult>& results,
                            const MeanConfidenceInterval& test_error) {
  std::ostringstream md;
  md << "# VAE test error (" << DescribeVae(options) << ", " << options.epochs << " epochs, "
     << results.size() << " seeds)\n\n"
     << "| Model (latent dim.) | Mean | 95% CI | Std. dev |\n|---|---|---|---|\n"
     << "| " << PaperModelName(options) << " | " << Fixed(test_error.mean, 2) << " | ["
     << Fixed(test_error.low, 2) << ", " << Fixed(test_error.high, 2) << "] | "
     << Fixed(test_error.sd, 3) << " |\n\n"
     << "Paper (latent 12, beta 1, 10 seeds): ShallowConvVAE 42.67 [42.58, 42.75] sd 0.097; "
        "DeepConvVAE 45.13 [40.72, 49.54] sd 5.036.\n\n"
     << "Test error = mean over test scans of (BCE summed over 180 rays + beta * KL summed over "
        "the latent), one sampled z per scan; CI = Student-t with n - 1 degrees of freedom.\n\n"
     << "| seed | test error | BCE | KL | active dims | seconds |\n|---|---|---|---|---|---|\n";
  for (const SeedResult& r : results) {
    md << "| " << r.index << " | " << Fixed(r.test_error, 3) << " | " << Fixed(r.test_bce, 3)
       << " | " << Fixed(r.test_kl, 3) << " | " << r.active_dimensions << " | "
       << Fixed(r.seconds, 1) << " |\n";
  }
  return md.str();
}

}  // namespace

nlohmann::json SeedResultToJson(const SeedResult& result) {
  nlohmann::json history = nlohmann::json::array();
  for (const EpochLosses& h : result.history) {
    history.push_back({{"epoch", h.epoch},
                       {"train_bce", h.train_bce},
                       {"train_kl", h.train_kl},
                       {"val_bce", h.validation_bce},
                       {"val_kl", h.validation_kl},
                       {"seconds", h.seconds}});
  }
  return {{"index", result.index},
          {"seed", result.seed},
          {"test_error", result.test_error},
          {"test_bce", result.test_bce},
          {"test_kl", result.test_kl},
          {"active_dims", result.active_dimensions},
          {"kl_per_dim", result.kl_per_dimension},
          {"seconds", result.seconds},
          {"history", history}};
}

SeedResult SeedResultFromJson(const nlohmann::json& json, const std::string& origin) {
  try {
    SeedResult result;
    result.index = json.at("index").get<std::int64_t>();
    result.seed = json.at("seed").get<std::uint64_t>();
    result.test_error = json.at("test_error").get<double>();
    result.test_bce = json.at("test_bce").get<double>();
    result.test_kl = json.at("test_kl").get<double>();
    result.active_dimensions = json.at("active_dims").get<std::int64_t>();
    result.kl_per_dimension = json.at("kl_per_dim").get<std::vector<double>>();
    result.seconds = json.at("seconds").get<double>();
    for (const nlohmann::json& h : json.at("history")) {
      result.history.push_back({h.at("epoch").get<std::int64_t>(), h.at("train_bce").get<double>(),
                                h.at("train_kl").get<double>(), h.at("val_bce").get<double>(),
                                h.at("val_kl").get<double>(), h.at("seconds").get<double>()});
    }
    return result;
  } catch (const nlohmann::json::exception& error) {
    throw UserError(origin + ": malformed result (" + error.what() + ")");
  }
}

std::string LossesCsv(const std::vector<EpochLosses>& history) {
  std::ostringstream csv;
  csv << "epoch,train_bce,train_kl,val_bce,val_kl,seconds\n";
  csv.precision(9);
  for (const EpochLosses& h : history) {
    csv << h.epoch << ',' << h.train_bce << ',' << h.train_kl << ',' << h.validation_bce << ','
        << h.validation_kl << ',' << h.seconds << '\n';
  }
  return csv.str();
}

std::string PaperModelName(const VaeTrainingOptions& options) {
  return std::string(options.model.architecture == VaeArchitecture::kDeep ? "DeepConvVAE"
                                                                          : "ShallowConvVAE") +
         " (" + std::to_string(options.model.latent_dims) + ")";
}

void WriteRunSummary(const std::filesystem::path& run_dir, const VaeTrainingOptions& options,
                     const std::vector<SeedResult>& results) {
  const MeanConfidenceInterval test_error =
      Summarise(Collect(results, [](const SeedResult& r) { return r.test_error; }));
  const MeanConfidenceInterval seconds =
      Summarise(Collect(results, [](const SeedResult& r) { return r.seconds; }));
  const MeanConfidenceInterval active = Summarise(Collect(
      results, [](const SeedResult& r) { return static_cast<double>(r.active_dimensions); }));
  nlohmann::json seeds = nlohmann::json::array();
  for (const SeedResult& result : results) {
    nlohmann::json entry = SeedResultToJson(result);
    entry.erase("history");  // in seed_<k>/losses.csv
    seeds.push_back(entry);
  }
  const nlohmann::json summary = {
      {"model", PaperModelName(options)},
      {"architecture", VaeArchitectureName(options.model.architecture)},
      {"latent_dims", options.model.latent_dims},
      {"beta", options.beta},
      {"decoder_padding",
       options.model.decoder_padding == DecoderPadding::kZero ? "zero" : "circular"},
      {"epochs", options.epochs},
      {"data", options.data_path},
      {"test_error", ConfidenceIntervalJson(test_error)},
      {"test_error_per_seed", Collect(results, [](const SeedResult& r) { return r.test_error; })},
      {"active_dims", ConfidenceIntervalJson(active)},
      {"seconds_per_seed", ConfidenceIntervalJson(seconds)},
      {"seeds", seeds}};
  WriteTextFileAtomically(run_dir / "summary.json", summary.dump(2) + "\n");
  WriteTextFileAtomically(run_dir / "summary.md", SummaryMarkdown(options, results, test_error));
}

}  // namespace colav
