#include "reproduce/compaction_effect.hpp"

#include <cmath>
#include <fstream>
#include <limits>
#include <nlohmann/json.hpp>

#include "output/format_text.hpp"

namespace swarmagg {
namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

double error_or_nan(const std::vector<VariantError>* errors, const std::string& variant) {
  if (!errors) return kNaN;
  for (const VariantError& e : *errors) {
    if (e.variant == variant) return e.error;
  }
  return kNaN;
}

bool is_growth(const RateRow& row) {
  return row.term == "growth" || row.term == "join";
}

// Observed growths over those the model's capture radius expects for the same exposure (every
// size pooled). The variants share the growth term, so the first one speaks for all.
double growth_vs_model(const std::vector<RateRow>& rows) {
  double observed = 0.0, expected = 0.0;
  for (const RateRow& row : rows) {
    if (!is_growth(row) || row.models.empty()) continue;
    observed += static_cast<double>(row.estimate.events);
    expected += row.models.front().rate * row.estimate.exposure;
  }
  return expected > 0.0 ? observed / expected : kNaN;
}

double escape_fraction(const std::vector<RateRow>& rows) {
  double attempts = 0.0, escapes = 0.0;
  for (const RateRow& row : rows) {
    if (row.term == "attempt") attempts += static_cast<double>(row.estimate.events);
    if (row.term == "escape") escapes += static_cast<double>(row.estimate.events);
  }
  return attempts > 0.0 ? escapes / attempts : kNaN;
}

double final_noa(const FigureResult& r) {
  if (!r.noa || r.noa->simulation.steps.empty()) return kNaN;
  return r.noa->simulation.mean_at(r.noa->simulation.steps.size() - 1);
}

std::string csv_value(double value) {
  return std::isnan(value) ? "" : format_text("%.6g", value);
}

}  // namespace

OnOff CompactionEffect::error(const std::string& variant) const {
  for (std::size_t i = 0; i < variants.size(); ++i) {
    if (variants[i] == variant) return errors[i];
  }
  return {kNaN, kNaN};
}

CompactionEffect compaction_effect(const FigureResult& on, const FigureResult& off) {
  CompactionEffect e;
  e.figures = on.figure.figures;
  e.world = on.worlds.front().name;
  e.bayindir = on.noa.has_value();
  if (const std::vector<VariantError>* errors = model_errors(on)) {
    for (const VariantError& error : *errors) {
      e.variants.push_back(error.variant);
      e.errors.push_back({error.error, error_or_nan(model_errors(off), error.variant)});
    }
  }
  e.final_noa = {final_noa(on), final_noa(off)};
  e.member_spacing = {on.summary.member_spacing.value_or(kNaN),
                      off.summary.member_spacing.value_or(kNaN)};
  e.inside_attempt_share = {on.summary.inside_attempt_share.value_or(kNaN),
                            off.summary.inside_attempt_share.value_or(kNaN)};
  e.growth_vs_model = {growth_vs_model(on.rates), growth_vs_model(off.rates)};
  e.escape_fraction = {escape_fraction(on.rates), escape_fraction(off.rates)};
  return e;
}

std::string compaction_csv(const std::vector<CompactionEffect>& effects) {
  std::string text = "figure,world,compaction,quantity,value\n";
  for (const CompactionEffect& e : effects) {
    std::vector<std::pair<std::string, OnOff>> quantities;
    for (std::size_t i = 0; i < e.variants.size(); ++i)
      quantities.emplace_back("error:" + e.variants[i], e.errors[i]);
    quantities.emplace_back("final_noa", e.final_noa);
    quantities.emplace_back("member_spacing", e.member_spacing);
    quantities.emplace_back("growth_vs_model", e.growth_vs_model);
    quantities.emplace_back("escape_fraction", e.escape_fraction);
    quantities.emplace_back("inside_attempt_share", e.inside_attempt_share);
    for (const auto& [name, value] : quantities) {
      for (const bool enabled : {true, false}) {
        text += e.figures + "," + e.world + "," + (enabled ? "on" : "off") + "," + name + "," +
                csv_value(enabled ? value.on : value.off) + "\n";
      }
    }
  }
  return text;
}

}  // namespace swarmagg
