#pragma once
/// `insmc gap-validate` (docs/gap.md): the diagnosis run blind on truth-level
/// records with one named effect (or none) switched on, at several
/// magnitudes and seeds. The data come from the truth simulator
/// (lib/truth), never from the diagnosis' candidate models; the records are
/// stripped of their `truth.` keys before the diagnosis sees them.
#include <cstdint>
#include <string>
#include <vector>

#include "montecarlo/records/gap/diagnosis.h"
#include "montecarlo/records/gap/validation/writer_conventions.h"
#include "montecarlo/report/report.h"
#include "lib/records/record.h"
#include "lib/truth/effect.h"

namespace insmc::gap {

struct ValidationOptions {
  bool quick = false;
  int runs_per_file = 20;
  std::vector<double> magnitudes = {1.0, 3.0, 10.0, 30.0};  ///< factors on the effect's defaults
  int seeds = 3;                                    ///< files per (effect, magnitude)
  int null_files = 100;                             ///< files with no effect
  double alpha = 0.01;
  std::uint64_t seed = 1000;
  /// Effects to validate (names of the registry); empty: every effect. A
  /// file's seed depends only on (seed, effect, magnitude, file), so a
  /// subset reproduces the full study's files.
  std::vector<std::string> effects;
  /// The files as gap-validate's own simulator writes them, or rewritten in
  /// another recorder's conventions (writer_conventions.h: the foreign
  /// writer's, or the layout fuzzer's), each file its own.
  RecordWriter writer = RecordWriter::kOwn;
  bool other_writer() const { return writer != RecordWriter::kOwn; }
  DiagnosisProgress progress;  ///< files diagnosed; may be empty
  /// The quick CI subset: 10-run files, one dominant magnitude (30x), one seed, 4 null files.
  static ValidationOptions quick_subset();
};

/// Checks every setting's range (the diagnosis' own by validate() of
/// DiagnosisOptions); throws InputError naming the option of
/// `insmc gap-validate` that sets it.
void validate(const ValidationOptions& options);

/// One blind diagnosis of one file.
struct ValidationCase {
  std::string effect;      ///< "none" for null data
  double magnitude = 0;    ///< factor on the defaults
  int seed = 0;
  bool significant = false;
  std::string top;         ///< the diagnosis' top effect or class ("" if not ranked)
  bool identified = false; ///< top names the effect (alone or in a class of two)
  double shrink = 0;       ///< of the top candidate on held-out runs
  double recovered_ratio = 0;  ///< fitted / true of the magnitude parameter (0: not comparable)
  double gap = 0, p_value = 1;
  double seconds = 0;      ///< wall time of the diagnosis (null calibration included)
  std::string conventions; ///< the file's writer conventions (writer_conventions.h), or "" for the own
};

/// The targets are judged at the magnitudes where the effect is detectable:
/// more than half of that magnitude's files have a significant gap. A
/// significant file at a magnitude where the effect is not detectable is a
/// chance detection (the false-alarm rate, a target of its own); it is
/// counted in the strict figures, which are reported beside.
struct EffectScore {
  std::string effect;
  std::vector<double> detectable_magnitudes;
  int detected = 0, identified = 0;   ///< significant files at detectable magnitudes, and named
  double identification_rate = 0;     ///< identified / detected
  double median_shrink = 0;           ///< among the detected files
  int significant_cases = 0, identified_anywhere = 0;  ///< strict: every significant file
  double detection_threshold = 0;     ///< least magnitude identified in ≥ 90 % of its files (0: none)
  double median_recovered_ratio = 0;
};

struct ValidationResult {
  std::vector<ValidationCase> cases;
  std::vector<EffectScore> scores;
  int null_files = 0, false_alarms = 0;
  double false_alarm_p = 1.0;                         ///< P(≥ false_alarms | null_files, alpha)
  double false_alarm_low = 0, false_alarm_high = 1;   ///< Clopper–Pearson 95 % interval of the rate
  double median_shrink = 0;             ///< over the detected files of every effect
  double median_seconds = 0, max_seconds = 0;  ///< wall time per file's diagnosis
  std::vector<std::string> failures;    ///< targets not met, one line each
  std::vector<std::string> undetectable;  ///< effects no magnitude tried makes detectable
};

ValidationResult validate_diagnosis(const ValidationOptions& options);

/// A study file as validate_diagnosis writes it, blind (no truth keys):
/// `runs` runs of `seed` with `effects`, system 1 at 45°, T = 15 min and
/// 90 min of navigation, in insmc's own layout or in `layout`.
RecordFile own_layout_file(const std::vector<EffectSpec>& effects, std::uint64_t seed, int runs);
RecordFile file_in_conventions(const std::vector<EffectSpec>& effects, std::uint64_t seed, int runs,
                               const WriterConventions& layout);

/// The confusion matrix: files per true effect (rows: "none", then the
/// registry's effects) and reported top (columns, first seen first: an
/// effect, "(not ranked)" or "no gap").
struct Confusion {
  std::vector<std::string> rows, columns;
  std::vector<std::vector<int>> counts;  ///< [row][column]
};

/// gap-validate's set: validation.md, confusion.md, confusion.csv,
/// validation.json and the confusion matrix drawn (confusion); stdout
/// validation.md.
mc::ReportOutline validation_report_outline();

mc::Report validation_report(const ValidationResult& r, const ValidationOptions& options);

}  // namespace insmc::gap
