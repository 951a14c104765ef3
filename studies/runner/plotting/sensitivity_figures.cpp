#include "studies/runner/plotting/sensitivity_figures.hpp"

#include <cmath>
#include <sstream>

#include "studies/runner/output/atomic_file.hpp"

namespace orni::studies {

namespace {

std::string cell(const std::optional<double>& v) {
  return v && std::isfinite(*v) ? formatShortest(*v) : std::string();
}

/// A gnuplot double-quoted string of `s` (a '"' is escaped; "\\n" in `s` is a line break there).
/// Not named `quoted`: argument-dependent lookup would prefer std::quoted for a non-const string.
std::string gnuplotString(const std::string& s) {
  std::string out = "\"";
  for (const char c : s) {
    if (c == '"') out += '\\';
    out += c;
  }
  return out + "\"";
}

/// A short number for titles: 4 significant digits.
std::string shortNumber(double v) {
  std::ostringstream s;
  s.precision(4);
  s << v;
  return s.str();
}

}  // namespace

std::string parameterLabel(const SensitivityParameter& p) {
  const std::string unit = keyUnit(p.key);
  std::string label = p.key + ": " + formatShortest(p.low) + " .. " + formatShortest(p.high);
  if (unit != "-") label += " " + unit;
  if (std::isfinite(p.base)) label += " (base " + formatShortest(p.base) + ")";
  return label;
}

std::string tornadoStem(const PredictionRanking& ranking) {
  return "tornado_" + sensitivityResultColumns()[ranking.column].name;
}

CsvTable tornadoTable(const Study& study, const std::vector<PredictionRanking>& rankings) {
  const std::vector<SensitivityParameter>& params = study.sensitivity().parameters;
  const std::vector<SensitivityColumn>& columns = sensitivityResultColumns();
  struct Row {
    std::size_t prediction, rank;  // 0-based
    const PredictionRanking* ranking;
    const SensitivityEffect* effect;
  };
  std::vector<Row> rows;
  for (std::size_t k = 0; k < rankings.size(); ++k)
    for (std::size_t r = 0; r < rankings[k].ranked.size(); ++r)
      rows.push_back({k, r, &rankings[k], &rankings[k].ranked[r]});
  auto column = [&](const Row& r) -> const SensitivityColumn& {
    return columns[r.ranking->column];
  };
  auto param = [&](const Row& r) -> const SensitivityParameter& {
    return params[r.effect->parameter];
  };
  return RowTable("tornado.csv", rows)
      .text("prediction", [&](const Row& r) { return column(r).name; })
      .text("prediction_unit", [&](const Row& r) { return column(r).unit; })
      .text("prediction_index", [](const Row& r) { return std::to_string(r.prediction + 1); })
      .text("rank", [](const Row& r) { return std::to_string(r.rank + 1); })
      .text("parameter", [&](const Row& r) { return param(r).key; })
      .text("parameter_index", [](const Row& r) { return std::to_string(r.effect->parameter + 1); })
      .text("label", [&](const Row& r) { return parameterLabel(param(r)); })
      .text("base", [](const Row& r) { return cell(r.ranking->base); })
      .text("low_value", [](const Row& r) { return cell(r.effect->low_value); })
      .text("high_value", [](const Row& r) { return cell(r.effect->high_value); })
      .text("delta_low", [](const Row& r) { return cell(r.effect->delta_low); })
      .text("delta_high", [](const Row& r) { return cell(r.effect->delta_high); })
      .text("swing", [](const Row& r) { return cell(r.effect->swing); })
      .text("swing_share", [](const Row& r) { return cell(r.effect->swing_share); })
      .table();
}

std::string tornadoFigure(const Study& study, const std::vector<PredictionRanking>& rankings,
                          std::size_t k) {
  const PredictionRanking& p = rankings[k];
  bool any = false;
  for (const SensitivityEffect& e : p.ranked) any = any || e.delta_low || e.delta_high;
  if (!any) return {};
  using C = TornadoCsvColumns;
  const SensitivityColumn& col = sensitivityResultColumns()[p.column];
  const std::vector<SensitivityParameter>& params = study.sensitivity().parameters;
  const std::size_t n = p.ranked.size();
  const std::size_t first = k * n, last = first + n - 1;  // data rows of this prediction
  const std::string unit = col.unit == "-" ? std::string() : " " + col.unit;
  const std::string y = "(" + std::to_string(n + 1) + "-$" + std::to_string(C::kRank) + ")";
  const std::string rows =
      "'tornado.csv' skip 2 every ::" + std::to_string(first) + "::" + std::to_string(last);
  auto bar = [&](int delta_col, const char* y_lo, const char* y_hi, const char* colour,
                 const char* title) {
    const std::string d = "$" + std::to_string(delta_col);
    std::ostringstream b;
    b << rows << " using (0.5*" << d << "):" << y << ":(lo(" << d << ")):(hi(" << d << ")):(" << y
      << y_lo << "):(" << y << y_hi << ") with boxxyerror lc rgb '" << colour << "' title '"
      << title << "'";
    return b.str();
  };
  // The value at the end of each bar: left of a negative bar, right of a positive one.
  auto values = [&](int delta_col, const char* dy, bool negative) {
    const std::string d = "$" + std::to_string(delta_col);
    std::ostringstream v;
    v << rows << " using (" << d << (negative ? "<0?" : ">=0?") << d << ":1/0):(" << y << dy
      << "):(sprintf('%+.3g', " << d << ")) with labels "
      << (negative ? "right offset -0.5,0" : "left offset 0.5,0") << " font ',9' notitle";
    return v.str();
  };
  // Elements with at least one point only: gnuplot 5.4 fails on an element without a valid
  // point (and crashes on such a `with labels` beside others).
  bool low_any = false, high_any = false, low_neg = false, low_pos = false, high_neg = false,
       high_pos = false;
  for (const SensitivityEffect& e : p.ranked) {
    if (e.delta_low) {
      low_any = true;
      (*e.delta_low < 0 ? low_neg : low_pos) = true;
    }
    if (e.delta_high) {
      high_any = true;
      (*e.delta_high < 0 ? high_neg : high_pos) = true;
    }
  }
  std::vector<std::string> elements;
  if (low_any)
    elements.push_back(bar(C::kDeltaLow, "-0.4", "", "#2471a3", "parameter at the low end"));
  if (high_any)
    elements.push_back(bar(C::kDeltaHigh, "", "+0.4", "#c0392b", "parameter at the high end"));
  if (low_neg) elements.push_back(values(C::kDeltaLow, "-0.2", true));
  if (low_pos) elements.push_back(values(C::kDeltaLow, "-0.2", false));
  if (high_neg) elements.push_back(values(C::kDeltaHigh, "+0.2", true));
  if (high_pos) elements.push_back(values(C::kDeltaHigh, "+0.2", false));

  std::ostringstream g;
  // Title lines centred on the canvas (the plot area is shifted right by the long labels).
  g << "set label 101 " << gnuplotString(study.name + ": " + col.name + " (" + col.label + ")")
    << " at screen 0.5, 0.975 center noenhanced font ',13'\n";
  g << "set label 102 "
    << gnuplotString(
           "base vehicle: " + (p.base ? shortNumber(*p.base) + unit : std::string("no value")) +
           "; bars: the change with the parameter at the low and at the high end of its "
           "range, largest swing on top")
    << " at screen 0.5, 0.945 center noenhanced font ',10'\n";
  g << "set tmargin at screen 0.91\n";
  g << "set xlabel "
    << gnuplotString("change of " + col.name + " from the base vehicle's value" +
                     (col.unit == "-" ? std::string() : " (" + col.unit + ")"))
    << " noenhanced\n";
  g << "set lmargin at screen 0.40\nset rmargin at screen 0.96\n";
  g << "set yrange [0.4:" << n + 0.6 << "]\n";
  g << "set ytics (";
  for (std::size_t r = 0; r < n; ++r) {
    const SensitivityEffect& e = p.ranked[r];
    std::string label = parameterLabel(params[e.parameter]);
    if (!e.delta_low || !e.delta_high) {  // say which end has no bar (the point's status says why)
      const char* which = !e.delta_low && !e.delta_high ? "either end"
                          : !e.delta_low                ? "low"
                                                        : "high";
      label += std::string("\\nno value at ") + which + ": see sensitivity.csv";
    }
    g << (r ? ", " : "") << gnuplotString(label) << " " << n - r;
  }
  g << ") noenhanced font ',9'\n";
  g << "set grid noytics\n";
  g << "set offsets graph 0.18, graph 0.18, 0, 0\n";
  g << "set style fill solid 0.85 border rgb '#333333'\n";
  g << "set key bottom right box opaque\n";
  g << "lo(d) = d < 0 ? d : 0\nhi(d) = d > 0 ? d : 0\n";
  g << "set arrow 1 from first 0, graph 0 to first 0, graph 1 nohead lw 2 lc rgb '#333333'\n";
  g << "plot ";
  for (std::size_t i = 0; i < elements.size(); ++i) g << (i ? ", \\\n  " : "") << elements[i];
  g << "\n";
  return g.str();
}

std::string overviewFigure(const Study& study, const std::vector<PredictionRanking>& rankings) {
  bool any = false;
  for (const PredictionRanking& p : rankings)
    for (const SensitivityEffect& e : p.ranked) any = any || e.swing_share;
  if (!any) return {};
  using C = TornadoCsvColumns;
  const std::vector<SensitivityParameter>& params = study.sensitivity().parameters;
  const std::size_t n = params.size();
  const std::string x = "($" + std::to_string(C::kPredictionIndex) + ")";
  const std::string y =
      "(" + std::to_string(n + 1) + "-$" + std::to_string(C::kParameterIndex) + ")";
  const std::string share = "($" + std::to_string(C::kSwingShare) + ")";
  std::ostringstream g;
  // Title lines centred on the canvas (the plot area is shifted right by the long labels).
  g << "set label 101 "
    << gnuplotString(study.name + ": the swing of each prediction over each parameter's range")
    << " at screen 0.5, 0.975 center noenhanced font ',13'\n";
  g << "set label 102 "
    << gnuplotString(
           "as a share of that prediction's largest swing (in brackets); empty: an end "
           "without a value (see tornado_<prediction> and sensitivity.csv)")
    << " at screen 0.5, 0.945 center noenhanced font ',10'\n";
  g << "set tmargin at screen 0.91\n";
  g << "set lmargin at screen 0.30\nset bmargin at screen 0.22\nset rmargin at screen 0.88\n";
  g << "set xrange [0.5:" << rankings.size() + 0.5 << "]\nset yrange [0.5:" << n + 0.5 << "]\n";
  g << "set xtics (";  // each prediction with its largest swing: the scale of its column
  for (std::size_t k = 0; k < rankings.size(); ++k) {
    const SensitivityColumn& col = sensitivityResultColumns()[rankings[k].column];
    std::optional<double> largest;
    for (const SensitivityEffect& e : rankings[k].ranked)
      if (e.swing && (!largest || *e.swing > *largest)) largest = e.swing;
    const std::string scale =
        largest ? shortNumber(*largest) + (col.unit == "-" ? "" : " " + col.unit) : "-";
    g << (k ? ", " : "") << gnuplotString(col.name + " (" + scale + ")") << " " << k + 1;
  }
  g << ") rotate by 40 right noenhanced font ',9'\n";
  g << "set ytics (";
  for (std::size_t i = 0; i < n; ++i)
    g << (i ? ", " : "") << gnuplotString(params[i].key) << " " << n - i;
  g << ") noenhanced font ',9'\n";
  g << "unset grid\nunset key\n";
  g << "set cbrange [0:1]\nset palette defined (0 '#ffffff', 1 '#c0392b')\n";
  g << "set cblabel 'swing / largest swing of the prediction'\n";
  g << "set style fill solid 1.0 border rgb '#999999'\n";
  g << "plot 'tornado.csv' skip 2 using " << x << ":" << y << ":(" << x << "-0.5):(" << x
    << "+0.5):(" << y << "-0.5):(" << y << "+0.5):" << share
    << " with boxxyerror lc palette, \\\n  'tornado.csv' skip 2 using " << x << ":" << y
    << ":(sprintf('%.2f', " << share << ")) with labels font ',8'\n";
  return g.str();
}

}  // namespace orni::studies
