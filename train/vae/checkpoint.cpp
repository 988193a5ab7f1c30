#include "train/vae/checkpoint.h"

#include "src/atomic_file.h"
#include "src/error.h"

namespace colav {
namespace {

constexpr int kHistoryColumns = 6;

torch::Tensor HistoryTensor(const std::vector<EpochLosses>& history) {
  torch::Tensor table =
      torch::zeros({static_cast<std::int64_t>(history.size()), kHistoryColumns}, torch::kDouble);
  auto rows = table.accessor<double, 2>();
  for (std::size_t e = 0; e < history.size(); ++e) {
    const EpochLosses& h = history[e];
    const double values[kHistoryColumns] = {static_cast<double>(h.epoch),
                                            h.train_bce,
                                            h.train_kl,
                                            h.validation_bce,
                                            h.validation_kl,
                                            h.seconds};
    for (int c = 0; c < kHistoryColumns; ++c) rows[static_cast<std::int64_t>(e)][c] = values[c];
  }
  return table;
}

std::vector<EpochLosses> HistoryFromTensor(const torch::Tensor& table) {
  std::vector<EpochLosses> history;
  const auto rows = table.accessor<double, 2>();
  for (std::int64_t e = 0; e < table.size(0); ++e) {
    history.push_back({static_cast<std::int64_t>(rows[e][0]), rows[e][1], rows[e][2], rows[e][3],
                       rows[e][4], rows[e][5]});
  }
  return history;
}

}  // namespace

void SaveVaeCheckpoint(const std::filesystem::path& path, const std::string& signature,
                       ConvVae& model, Adam& optimizer, const VaeProgress& progress) {
  torch::serialize::OutputArchive archive;
  torch::serialize::OutputArchive model_archive;
  model->save(model_archive);
  torch::serialize::OutputArchive optimizer_archive;
  optimizer.Save(optimizer_archive);
  archive.write("model", model_archive);
  archive.write("optimizer", optimizer_archive);
  archive.write("signature", c10::IValue(signature));
  archive.write("history", HistoryTensor(progress.history));
  archive.write("seconds", torch::tensor(progress.seconds, torch::kDouble));
  WriteFileAtomically(
      path, [&](const std::filesystem::path& temporary) { archive.save_to(temporary.string()); });
}

VaeProgress LoadVaeCheckpoint(const std::filesystem::path& path, const std::string& signature,
                              ConvVae& model, Adam& optimizer) {
  torch::serialize::InputArchive archive;
  c10::IValue stored_signature;
  torch::Tensor history;
  torch::Tensor seconds;
  try {
    archive.load_from(path.string());
    if (!archive.try_read("signature", stored_signature) || !stored_signature.isString()) {
      throw UserError(path.string() + ": not a train_vae checkpoint");
    }
    if (stored_signature.toStringRef() != signature) {
      throw UserError(path.string() + ": checkpoint of other settings (" +
                      stored_signature.toStringRef() + "); use another --out to start afresh");
    }
    torch::serialize::InputArchive model_archive;
    torch::serialize::InputArchive optimizer_archive;
    archive.read("model", model_archive);
    archive.read("optimizer", optimizer_archive);
    model->load(model_archive);
    optimizer.Load(optimizer_archive);
    archive.read("history", history);
    archive.read("seconds", seconds);
  } catch (const c10::Error&) {
    throw UserError(path.string() + ": cannot read checkpoint (damaged or truncated?)");
  }
  return {HistoryFromTensor(history), seconds.item<double>()};
}

}  // namespace colav
