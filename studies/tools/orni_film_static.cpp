// orni_film_static: the full-order nonlinear static wing under a uniform lift pressure with the
// skin's membrane law chosen (docs/theory.md 4.7, "A film that wrinkles"): the reference the
// reduced wing is checked against, and the scan of the film law's parameters.
//
//   orni_film_static VEHICLE.toml [--pressure PA] [--film elastic|tension-field]
//                    [--kappa K1,K2,...] [--cap NC1,NC2,...] [--increments N]
//                    [--max-newton N] [--kinematics von-karman|co-rotational] [--csv FILE]
//                    [--ccx-deck FILE.inp]
//
// One static solution (structure/von_karman.hpp, solveWingStatic: every retained DOF, Newton with
// load increments) per (kappa, cap) pair of the lists, at --pressure (default 53 Pa, about the
// rigid wing's lift per area at Table 3's point) on the vehicle's wing, its mesh and support. For
// each: the mid-span and tip sections (leading and trailing edge up, section pitch change), the
// film's facet states (taut, wrinkled, slack) and the largest skin slope |grad w| with the angle it
// stands for: von Karman's strains keep the squares of the slopes and drop their higher powers, so
// slopes well below 1 (angles below ~15 deg) are its range; above it the answer is a trend, not a
// number. --kinematics co-rotational solves the large-rotation wing instead (corotational.hpp),
// and the slope column is then the largest rotation of a facet's plane, as its tangent. The
// elastic film ignores --kappa and --cap (one solution). Exit status 3 when a solution did not
// converge (its line says why), 2 for bad arguments, 1 for a file that cannot be read.
// --ccx-deck also writes the same wing, support and pressure as a CalculiX deck with NLGEOM (S6
// skin, B32R rods, calculix_deck.hpp; an elastic skin whatever --film says: CalculiX has no
// wrinkling law), dead load, static steps at 10, 25, 50, 75 and 100 % of the load, printing the
// mid-span and tip sections' edge nodes (CalculiX node = our node + 1): `ccx -i FILE` runs it.
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <iostream>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include "core/structure/calculix_deck.hpp"
#include "core/structure/corotational.hpp"
#include "core/structure/dof_partition.hpp"
#include "core/structure/fe_assembly.hpp"
#include "core/structure/modal_wing.hpp"
#include "core/structure/static_shapes.hpp"
#include "core/structure/von_karman.hpp"
#include "core/structure/wing_mesh.hpp"
#include "studies/runner/config/vehicle_file.hpp"
#include "studies/tools/tool_args.hpp"

namespace {

using namespace orni;
using namespace orni::structure;

constexpr double kPi = 3.14159265358979323846;

struct Args {
  std::string vehicle;
  double pressure_pa = 53.0;
  bool tension_field = true;
  std::vector<double> kappas{kTensionFieldResidualStiffness};
  std::vector<double> caps{0.0};
  int increments = 10;
  int max_newton = 400;  // the film's Hessian jumps between states: 80-400 iterations an increment
  bool corotational = false;
  std::string csv;
  std::string ccx_deck;
};

[[noreturn]] void usage(const std::string& why) {
  tools::exitWithUsage("orni_film_static",
                       "orni_film_static VEHICLE.toml [--pressure PA] [--film elastic|tension-field]"
                       " [--kappa K1,K2,...] [--cap NC1,NC2,...] [--increments N] [--max-newton N]"
                       " [--kinematics von-karman|co-rotational] [--csv FILE] [--ccx-deck FILE.inp]",
                       why);
}

double toNumber(const std::string& option, const std::string& text) {
  if (const std::optional<double> v = tools::parseNumber(text)) return *v;
  usage(option + ": expected a number, got '" + text + "'");
}

int toInt(const std::string& option, const std::string& text) {
  if (const std::optional<int> v = tools::parseInt(text)) return *v;
  usage(option + ": expected an integer, got '" + text + "'");
}

std::vector<double> toList(const std::string& option, const std::string& text) {
  const std::optional<std::vector<double>> values = tools::parseNumberList(text);
  if (!values || values->empty()) usage(option + ": expected comma-separated numbers, got '" + text + "'");
  return *values;
}

Args parseArgs(int argc, char** argv) {
  Args a;
  auto value = [&](int& i) -> std::string {
    if (i + 1 >= argc) usage(std::string(argv[i]) + " needs a value");
    return argv[++i];
  };
  for (int i = 1; i < argc; ++i) {
    const std::string s = argv[i];
    if (s == "--csv") {
      a.csv = value(i);
    } else if (s == "--ccx-deck") {
      a.ccx_deck = value(i);
      if (a.ccx_deck.size() < 5 || a.ccx_deck.substr(a.ccx_deck.size() - 4) != ".inp")
        usage("--ccx-deck: expected a file name ending in .inp, got '" + a.ccx_deck + "'");
    } else if (s == "--pressure") {
      a.pressure_pa = toNumber(s, value(i));
    } else if (s == "--film") {
      const std::string f = value(i);
      if (f != "elastic" && f != "tension-field")
        usage("--film: expected elastic or tension-field, got '" + f + "'");
      a.tension_field = f == "tension-field";
    } else if (s == "--kappa") {
      a.kappas = toList(s, value(i));
    } else if (s == "--cap") {
      a.caps = toList(s, value(i));
    } else if (s == "--increments") {
      a.increments = toInt(s, value(i));
    } else if (s == "--kinematics") {
      const std::string k = value(i);
      if (k != "von-karman" && k != "co-rotational")
        usage("--kinematics: expected von-karman or co-rotational, got '" + k + "'");
      a.corotational = k == "co-rotational";
    } else if (s == "--max-newton") {
      a.max_newton = toInt(s, value(i));
    } else if (const std::string why = orni::tools::takeVehicleArgument(s, &a.vehicle); !why.empty()) {
      usage(why);
    }
  }
  if (a.vehicle.empty()) usage("no vehicle file");
  if (a.pressure_pa == 0.0) usage("--pressure: expected a nonzero pressure (Pa; > 0 lifts)");
  if (a.increments < 1 || a.max_newton < 1) usage("--increments and --max-newton: expected >= 1");
  if (!a.tension_field) {
    a.kappas = {kTensionFieldResidualStiffness};
    a.caps = {0.0};
  }
  for (const double k : a.kappas)
    for (const double c : a.caps) {
      FilmLaw law;
      law.residual_stiffness = k;
      law.compression_cap_n_per_m = c;
      std::string why;
      if (!law.IsValid(&why)) usage(why + " (--kappa, --cap)");
    }
  return a;
}

// The largest |grad w| over the skin facets (w normal to each facet's plane).
double largestSlope(const VonKarmanTerms& terms, const Eigen::VectorXd& u) {
  double largest = 0.0;
  for (const VonKarmanTerms::Facet& f : terms.facets()) {
    Eigen::Vector3d w;
    for (int a = 0; a < 3; ++a)
      w(a) = f.triad.row(2).dot(u.segment<3>(globalDof(f.nodes[static_cast<std::size_t>(a)], kU)));
    largest = std::max(largest, (f.grad * w).norm());
  }
  return largest;
}

}  // namespace

int main(int argc, char** argv) {
  const Args args = parseArgs(argc, argv);
  try {
    const VehicleDefinition def = studies::loadVehicleFile(args.vehicle);
    const VehicleModel& v = def.model;
    const WingMesh mesh = buildWingMesh(v, v.wing.fe.element_size_m);
    const ModalWingOptions mo = modalWingOptionsOf(v.wing.fe);
    const Eigen::VectorXd load = uniformLiftLoad(mesh, args.pressure_pa);
    const std::size_t mid = mesh.strip_nodes.size() / 2, tip = mesh.strip_nodes.size() - 1;
    std::printf("%s: %zu nodes, %zu facets, %zu members; %.2f Pa of lift, %s film, %s, %d "
                "increments\n",
                args.vehicle.c_str(), mesh.nodes_W_m.size(), mesh.triangles.size(),
                mesh.beams.size(), args.pressure_pa,
                args.tension_field ? "tension-field" : "elastic",
                args.corotational ? "co-rotational" : "von Karman", args.increments);
    if (!args.ccx_deck.empty()) {
      CalculixDeckOptions d;
      d.frequency_step = false;
      d.p3_joint = mo.support.p3_joint;
      d.p3_cross_axis_normal = mo.support.p3_cross_axis == UniversalJointCrossAxis::kZW;
      d.root_edge_pinned = mo.support.root_edge_pinned;
      d.static_steps.nlgeom = true;
      d.static_steps.load_factors = {0.1, 0.25, 0.5, 0.75, 1.0};
      d.static_steps.load.skin_pressure_pa = -args.pressure_pa;  // lift acts along -z_W
      for (const std::size_t strip : {mid, tip}) {
        d.static_steps.print_nodes.push_back(mesh.strip_nodes[strip].leading_edge);
        d.static_steps.print_nodes.push_back(mesh.strip_nodes[strip].trailing_edge);
      }
      std::ofstream deck(args.ccx_deck);
      deck << calculixDeck(v, mesh, d);
      if (!deck.flush()) throw std::runtime_error("cannot write " + args.ccx_deck);
      std::printf("CalculiX deck %s: mid-span LE / TE nodes %d / %d, tip %d / %d (CalculiX "
                  "numbering)\n",
                  args.ccx_deck.c_str(), mesh.strip_nodes[mid].leading_edge + 1,
                  mesh.strip_nodes[mid].trailing_edge + 1, mesh.strip_nodes[tip].leading_edge + 1,
                  mesh.strip_nodes[tip].trailing_edge + 1);
    }
    int failures = 0;
    std::ofstream csv;
    if (!args.csv.empty()) {
      csv.open(args.csv);
      if (!csv) throw std::runtime_error("cannot write " + args.csv);
      csv << "kappa,cap_N_per_m,converged,newton_iterations,mid_lead_up_mm,mid_trail_up_mm,"
             "mid_pitch_deg,tip_lead_up_mm,tip_trail_up_mm,tip_pitch_deg,taut,wrinkled,slack,"
             "largest_slope\n";
    }
    for (const double kappa : args.kappas)
      for (const double cap : args.caps) {
        NonlinearStaticOptions o;
        o.load_steps = args.increments;
        o.max_newton_iterations = args.max_newton;
        o.skin_membrane = args.tension_field ? SkinMembrane::kTensionField : SkinMembrane::kElastic;
        o.film.residual_stiffness = kappa;
        o.film.compression_cap_n_per_m = cap;
        o.kinematics = args.corotational ? StrainKinematics::kCoRotational
                                         : StrainKinematics::kVonKarman;
        const NonlinearStaticResult r = solveWingStatic(v, mesh, mo.support, load, o);
        if (!r.converged) ++failures;
        int counts[3] = {0, 0, 0};
        double slope = 0.0;
        if (args.corotational) {
          const CoRotationalTerms terms(v, mesh, assembleWingFe(v, mesh).stiffness,
                                        o.skin_membrane, o.film);
          for (const FilmState s : terms.facetStates(r.displacement)) ++counts[static_cast<int>(s)];
          slope = std::tan(terms.largestFacetTilt(r.displacement));
        } else {
          const VonKarmanTerms terms(v, mesh, MemberStretch::kBothTransverse, o.skin_membrane,
                                     o.film);
          for (const FilmState s : terms.facetStates(r.displacement)) ++counts[static_cast<int>(s)];
          slope = largestSlope(terms, r.displacement);
        }
        const Section m = sectionOf(mesh, r.displacement, mid), t = sectionOf(mesh, r.displacement, tip);
        std::printf("kappa %.1e, cap %.1f N/m: %s after %d Newton iterations\n"
                    "  mid-span: LE up %.3f mm, TE up %.3f mm, pitch %.2f deg\n"
                    "  tip:      LE up %.3f mm, TE up %.3f mm, pitch %.2f deg\n"
                    "  facets taut / wrinkled / slack: %d / %d / %d; largest skin slope %.3f "
                    "(%.1f deg)\n",
                    kappa, cap, r.converged ? "converged" : ("NOT converged: " + r.message).c_str(),
                    r.newton_iterations, 1e3 * m.lead_up_m, 1e3 * m.trail_up_m, m.pitch_deg,
                    1e3 * t.lead_up_m, 1e3 * t.trail_up_m, t.pitch_deg, counts[0], counts[1], counts[2], slope,
                    std::atan(slope) * 180.0 / kPi);
        std::fflush(stdout);
        if (csv) {
          char line[512];
          std::snprintf(line, sizeof line,
                        "%.6g,%.6g,%d,%d,%.6f,%.6f,%.4f,%.6f,%.6f,%.4f,%d,%d,%d,%.5f\n", kappa, cap,
                        r.converged ? 1 : 0, r.newton_iterations, 1e3 * m.lead_up_m,
                        1e3 * m.trail_up_m, m.pitch_deg, 1e3 * t.lead_up_m, 1e3 * t.trail_up_m,
                        t.pitch_deg, counts[0],
                        counts[1], counts[2], slope);
          csv << line << std::flush;
        }
      }
    if (failures > 0) {
      std::fprintf(stderr, "orni_film_static: %d of the solutions did not converge\n", failures);
      return 3;
    }
  } catch (const std::exception& e) {
    std::cerr << "orni_film_static: " << e.what() << "\n";
    return 1;
  }
  return 0;
}
