#include "train/vae/config.h"

#include <sstream>

#include "env/environment_config.h"
#include "src/error.h"

namespace colav {
namespace {

DecoderPadding ParseDecoderPadding(const std::string& name) {
  if (name == "circular") return DecoderPadding::kCircular;
  if (name == "zero") return DecoderPadding::kZero;
  throw UserError("unknown decoder padding '" + name + "' (expected circular or zero)");
}

std::string DecoderPaddingName(DecoderPadding padding) {
  return padding == DecoderPadding::kZero ? "zero" : "circular";
}

// Scans per batch at most (720 bytes each, and a model's activations many times that).
constexpr std::int64_t kMaxBatch = 1 << 20;

void RequireDataPath(VaeTrainingOptions& options) {
  if (options.data_path.empty()) throw UserError("data.path: no dataset given (use --data)");
}

}  // namespace

OptionsBinding<VaeTrainingOptions> VaeTrainingBinding() {
  using Options = VaeTrainingOptions;
  OptionsBinding<Options> binding;
  binding.Text("data.path", &Options::data_path, "dataset file written by generate_dataset (HDF5)")
      .Coded("data.transform", &Options::transform,
             "range -> closeness: linear 1 - d/150 (paper) or log (the reference environment's)",
             ClosenessTransformCodec(), {"linear", "log"})
      .Number("data.train_noise_variance", &Options::train_noise_variance,
              "variance of the Gaussian noise added to the training split (paper: 0.007)", 0.0, 1.0)
      .Bool("data.clip_noisy_scans", &Options::clip_noisy_scans,
            "clip the noisy training scans to [0, 1] (the reference does not; unclipped, BCE is "
            "unbounded below and DeepConvVAE exploits it)")
      .Coded("vae.model", [](Options & o) -> auto& { return o.model.architecture; },
             "ShallowConvVAE or DeepConvVAE",
             TextCodec<VaeArchitecture>{VaeArchitectureName, ParseVaeArchitecture},
             {"shallow", "deep"})
      .Number(
          "vae.latent_dims", [](Options & o) -> auto& { return o.model.latent_dims; },
          "latent dimensions", 1, 4096)
      .Number("vae.beta", &Options::beta, "weight of the KL term", 0.0, 1000.0)
      .Coded("vae.decoder_padding", [](Options & o) -> auto& { return o.model.decoder_padding; },
             "decoder transposed convolutions: circular (CPTC-1D) or zero padding (for the "
             "comparison figure)",
             TextCodec<DecoderPadding>{DecoderPaddingName, ParseDecoderPadding},
             {"circular", "zero"})
      .Number("training.epochs", &Options::epochs, "epochs per seed", 1, 100000)
      .Number("training.batch_size", &Options::batch_size, "minibatch size", 1, kMaxBatch)
      .Number("training.learning_rate", &Options::learning_rate,
              "Adam learning rate (otherwise Adam's default settings)", 0.0, 1.0)
      .Number("training.seeds", &Options::seeds,
              "independent training runs (seed_0 ... seed_<n-1>; the paper's table uses 10)", 1,
              1000)
      .Number("training.seed", &Options::seed,
              "master seed: initialisation, shuffles, noise, samples", 0)
      .Number("training.threads", &Options::threads,
              "LibTorch threads (1 is fastest for these small models on 2 cores)", 1, 256)
      .Number("evaluation.batch_size", &Options::evaluation_batch_size,
              "scans per batch when evaluating", 1, kMaxBatch)
      .Bool("figures.enabled", &Options::figures,
            "draw reconstructions and training curves into RUN_DIR")
      .Then(RequireDataPath);
  return binding;
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
