#include "train/vae/config.h"

#include <sstream>

#include "src/error.h"
#include "train/vae/data.h"

namespace colav {

ConfigSchema VaeTrainingSchema() {
  ConfigSchema schema;
  schema.AddString("data.path", "", "dataset file written by generate_dataset (HDF5)")
      .AddString("data.transform", "linear", "range -> closeness: linear 1 - d/150 (paper) or log",
                 {"linear", "log"})
      .AddDouble("data.train_noise_variance", 0.007,
                 "variance of the Gaussian noise added to the training split (paper: 0.007)", 0.0)
      .AddBool("data.clip_noisy_scans", false,
               "clip the noisy training scans to [0, 1] (the reference does not; unclipped, BCE is "
               "unbounded below and DeepConvVAE exploits it)")
      .AddString("vae.model", "shallow", "ShallowConvVAE or DeepConvVAE", {"shallow", "deep"})
      .AddInt("vae.latent_dims", 12, "latent dimensions", 1, 4096)
      .AddDouble("vae.beta", 1.0, "weight of the KL term", 0.0)
      .AddString("vae.decoder_padding", "circular",
                 "decoder transposed convolutions: circular (CPTC-1D) or zero padding",
                 {"circular", "zero"})
      .AddInt("training.epochs", 25, "epochs per seed", 1)
      .AddInt("training.batch_size", 64, "minibatch size", 1)
      .AddDouble("training.learning_rate", 1e-3, "Adam learning rate", 0.0)
      .AddInt("training.seeds", 1, "independent training runs (seed_0 ... seed_<n-1>)", 1, 1000)
      .AddInt("training.seed", 0, "master seed: initialisation, shuffles, noise, samples", 0)
      .AddInt("training.threads", 1,
              "LibTorch threads (1 is fastest for these small models on 2 cores)", 1, 256)
      .AddInt("evaluation.batch_size", 2048, "scans per batch when evaluating", 1)
      .AddBool("figures.enabled", true, "draw reconstructions and training curves into RUN_DIR");
  return schema;
}

VaeTrainingOptions VaeTrainingOptionsFrom(const Config& config) {
  VaeTrainingOptions options;
  options.data_path = config.GetString("data.path");
  if (options.data_path.empty()) throw UserError("data.path: no dataset given (use --data)");
  options.transform = ParseClosenessTransform(config.GetString("data.transform"), "data.transform");
  options.train_noise_variance = config.GetDouble("data.train_noise_variance");
  options.clip_noisy_scans = config.GetBool("data.clip_noisy_scans");
  options.model.architecture = ParseVaeArchitecture(config.GetString("vae.model"));
  options.model.latent_dims = config.GetInt("vae.latent_dims");
  options.model.decoder_padding = config.GetString("vae.decoder_padding") == "zero"
                                      ? DecoderPadding::kZero
                                      : DecoderPadding::kCircular;
  options.beta = config.GetDouble("vae.beta");
  options.epochs = config.GetInt("training.epochs");
  options.batch_size = config.GetInt("training.batch_size");
  options.learning_rate = config.GetDouble("training.learning_rate");
  options.seeds = config.GetInt("training.seeds");
  options.seed = static_cast<std::uint64_t>(config.GetInt("training.seed"));
  options.threads = static_cast<int>(config.GetInt("training.threads"));
  options.evaluation_batch_size = config.GetInt("evaluation.batch_size");
  options.figures = config.GetBool("figures.enabled");
  return options;
}

std::string DescribeVae(const VaeTrainingOptions& options) {
  std::ostringstream text;
  text << VaeArchitectureName(options.model.architecture) << ", latent "
       << options.model.latent_dims << ", beta " << options.beta << ", "
       << (options.model.decoder_padding == DecoderPadding::kZero ? "zero-padded" : "circular")
       << " decoder";
  return text.str();
}

}  // namespace colav
