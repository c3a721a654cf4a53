#include "stage/compare_options.hpp"

namespace furrow {

namespace {

OptionTable<CompareOptions> make_table() {
  using O = CompareOptions;
  OptionTable<O> t;
  OptionSpec<O> align = parsed_option<O>(
      "align", "A",
      "bestfit: a robust best fit, form only; cmm: the CMM program aligned the part, evaluated as measured, no "
      "fit; datums: the 3-2-1 datum frame from the plan's datum points, needs the plan, form + location; rps: "
      "the frame a reference point system fixes, needs the RPS file, form + location. cmm, datums and rps also "
      "give the best-fit profile (docs/registration.md \"Alignments\")",
      [](auto& o) -> auto& { return o.align; }, parse_align_method,
      [](AlignMethod a) { return std::string(to_string(a)); },
      choice_names({AlignMethod::bestfit, AlignMethod::cmm, AlignMethod::datums, AlignMethod::rps}));
  align.example = "cmm";
  t.push_back(align);
  OptionSpec<O> dof = parsed_option<O>(
      "dof", "D",
      "all, translation, rotation, or a list of rx,ry,rz,tx,ty,tz to fit; locked ones stay at zero and the fit "
      "starts from the CMM frame as is",
      [](auto& o) -> auto& { return o.registration.dof; }, DegreesOfFreedom::parse,
      [](const DegreesOfFreedom& d) { return d.to_string(); });
  dof.example = "rz,tx,ty";
  t.push_back(dof);
  OptionSpec<O> loss = parsed_option<O>(
      "loss", "L", "cauchy, huber or none, with the scale half the tolerance zone (first fit; the final fit after outlier "
      "rejection is least squares)",
      [](auto& o) -> auto& { return o.registration.loss; }, parse_robust_loss,
      [](RobustLoss l) { return std::string(to_string(l)); },
      choice_names({RobustLoss::cauchy, RobustLoss::huber, RobustLoss::none}));
  loss.example = "huber";
  t.push_back(loss);
  t.push_back(number_option<O>("outlier_sigma", "K", "robust sigmas that make a deviation large",
                               [](auto& o) -> auto& { return o.registration.outlier_sigma; }));
  t.push_back(toggle_option<O>("outlier_rejection",
                               "keep every point in the fit, flag no blunder or "
                               "large deviation",
                               [](auto& o) -> auto& { return o.registration.flag_outliers; }));
  t.push_back(number_option<O>("probe_sigma", "S",
                               "probing noise 1-sigma in mm",
                               [](auto& o) -> auto& { return o.prediction.probe_sigma; }));
  t.push_back(number_option<O>("explained_rms", "R",
                               "largest RMS of residual/sigma for \"explained\"",
                               [](auto& o) -> auto& { return o.prediction.max_normalised_rms; }));
  t.push_back(toggle_option<O>("prediction_alignment",
                               "compare best-fit deviations with the prediction "
                               "as they are, not aligned to the predicted surface first",
                               [](auto& o) -> auto& { return o.prediction.align; }));
  t.push_back(number_option<O>("overcut_sigmas", "K", "an overcut exceeds K sigma of the deviation ...",
                               [](auto& o) -> auto& { return o.gouges.overcut_sigmas; }));
  t.push_back(number_option<O>("overcut_fraction", "F",
                               "... and F times the zone's lower limit (0 to 1)",
                               [](auto& o) -> auto& { return o.gouges.tolerance_fraction; }, Bound::fraction));
  t.push_back(number_option<O>("site_margin", "M", "mm around a predicted site where points count",
                               [](auto& o) -> auto& { return o.gouges.site_margin; }, Bound::non_negative));
  t.push_back(number_option<O>("contact_cluster", "D", "local-gouge contacts within D mm form one site",
                               [](auto& o) -> auto& { return o.gouges.contact_cluster_distance; },
                               Bound::non_negative));
  t.push_back(number_option<O>("overcut_cluster", "D", "unexplained overcuts within D mm form one cluster",
                               [](auto& o) -> auto& { return o.gouges.overcut_cluster_distance; },
                               Bound::non_negative));
  return t;
}

}  // namespace

const OptionTable<CompareOptions>& compare_option_table() {
  static const OptionTable<CompareOptions> table = make_table();
  return table;
}

}  // namespace furrow
