// orni_flapping_reference: the full-order nonlinear wing in flapping flight against the reduced
// wing that produced its loads (docs/theory.md 4.7, "A flapping reference").
//
//   orni_flapping_reference VEHICLE.toml [--shapes P1,P2,...] [--modes N] [--rom-cycles N]
//                           [--full-cycles N] [--steps-per-cycle N] [--csv FILE] [--tension-field]
//                           [--film-cap NC]
//
// 1. The tethered run of the vehicle at its design point (the reduced nonlinear wing, the
//    vehicle's basis, or its modes with the nonlinear static shapes at --shapes) to its periodic
//    orbit (--rom-cycles), then one more cycle sampled --steps-per-cycle times: the modal state and
//    the strip loads the kernel gave (core/dynamics/strip_load_orbit.hpp) at every sample.
// 2. The full finite-element wing (structure/wing_transient.hpp: every retained DOF, the von Karman
//    terms, Newmark) driven over --full-cycles cycles by the same hinge motion, the same strip loads
//    on the same section nodes with the same chordwise weights and the same apparent air mass
//    (with the recorded separation fractions), from the reduced wing's state at the cycle's start.
// 3. The two wings' section twist, mid-chord deflection and tip deflection over the last cycle.
// --tension-field: the full wing's skin is a tension-field film (structure/tension_field.hpp), which
//    wrinkles instead of carrying compression; the reduced wing keeps its elastic membrane.
//    --film-cap NC (N/m, with --tension-field): the compression the wrinkled film keeps (its
//    wrinkles' buckling load, FilmLaw::compression_cap_n_per_m; default 0).
//
// If the full wing's response to the reduced orbit's loads is the reduced orbit, that orbit is
// (to the difference measured) also an orbit of the full model: the loads depend on the wing only
// through the section motion compared here. If not, the reduced basis is not converged in flight.
// The damping of the full wing is stiffness-proportional on its tangent with the reduced wing's
// first-mode ratio (wing_transient.hpp); the reduced wing's higher modes keep a constant ratio,
// a difference that matters only for modes near the flapping harmonics (reported: f_1).
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <functional>
#include <iostream>
#include <optional>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include <Eigen/SparseCore>

#include "core/dynamics/flapping.hpp"
#include "core/dynamics/flexible_wing.hpp"
#include "core/dynamics/flight_core.hpp"
#include "core/dynamics/strip_load_orbit.hpp"
#include "core/structure/fe_assembly.hpp"
#include "core/structure/skin_pretension.hpp"
#include "core/structure/wing_transient.hpp"
#include "studies/runner/config/vehicle_file.hpp"
#include "studies/tools/tool_args.hpp"

namespace {

using orni::structure::SparseMatrix;

struct Args {
  std::string vehicle;
  std::vector<double> shapes;
  bool shapes_given = false;
  int modes = 0;  // 0: the vehicle's
  int rom_cycles = 10;
  int full_cycles = 3;
  int steps = 200;
  std::string csv;
  bool tension_field = false;  // the full wing's skin a tension-field film (tension_field.hpp)
  double film_cap_npm = 0.0;   // its compression cap
};

[[noreturn]] void usage(const std::string& why) {
  orni::tools::exitWithUsage(
      "orni_flapping_reference",
      "orni_flapping_reference VEHICLE.toml [--shapes P1,P2,...] [--modes N] [--rom-cycles N]"
      " [--full-cycles N] [--steps-per-cycle N] [--csv FILE] [--tension-field] [--film-cap NC]",
      why);
}

int toInt(const std::string& option, const std::string& text) {
  if (const std::optional<int> v = orni::tools::parseInt(text)) return *v;
  usage(option + ": expected an integer, got '" + text + "'");
}

double toNumber(const std::string& option, const std::string& text) {
  if (const std::optional<double> v = orni::tools::parseNumber(text)) return *v;
  usage(option + ": expected a number, got '" + text + "'");
}

Args parseArgs(int argc, char** argv) {
  Args a;
  auto number = [&](int& i) -> std::string {
    if (i + 1 >= argc) usage(std::string(argv[i]) + " needs a value");
    return argv[++i];
  };
  for (int i = 1; i < argc; ++i) {
    const std::string s = argv[i];
    if (s == "--shapes") {
      a.shapes_given = true;
      const std::string list = number(i);
      const std::optional<std::vector<double>> shapes = orni::tools::parseNumberList(list);
      if (!shapes) usage(s + ": expected comma-separated numbers, got '" + list + "'");
      a.shapes = *shapes;
    } else if (s == "--modes") {
      a.modes = toInt(s, number(i));
    } else if (s == "--rom-cycles") {
      a.rom_cycles = toInt(s, number(i));
    } else if (s == "--full-cycles") {
      a.full_cycles = toInt(s, number(i));
    } else if (s == "--steps-per-cycle") {
      a.steps = toInt(s, number(i));
    } else if (s == "--tension-field") {
      a.tension_field = true;
    } else if (s == "--film-cap") {
      a.film_cap_npm = toNumber(s, number(i));
      if (a.film_cap_npm < 0.0) usage("--film-cap: expected a compression cap >= 0 N/m");
    } else if (s == "--csv") {
      a.csv = number(i);
    } else if (const std::string why = orni::tools::takeVehicleArgument(s, &a.vehicle); !why.empty()) {
      usage(why);
    }
  }
  if (a.vehicle.empty()) usage("no vehicle file");
  if (a.film_cap_npm > 0.0 && !a.tension_field) usage("--film-cap needs --tension-field");
  if (a.rom_cycles < 1 || a.full_cycles < 1 || a.steps < 8) usage("cycles >= 1, steps >= 8");
  return a;
}

// Nodal forms of the strip operators: twist and mid-chord normal rows (6n) per strip.
struct SectionRows {
  std::vector<Eigen::SparseVector<double>> twist, mid;
};

SectionRows sectionRows(const orni::FlexibleWingModel& flex, int dofs) {
  SectionRows r;
  for (const orni::FlexibleStrip& s : flex.strips) {
    Eigen::SparseVector<double> tw(dofs), mid(dofs);
    for (int i = 0; i < 4; ++i) {
      const int zdof = orni::structure::globalDof(s.section_nodes[static_cast<std::size_t>(i)], 2);
      const double a = s.force_weights[static_cast<std::size_t>(i)];
      const double b = s.moment_weights[static_cast<std::size_t>(i)];
      // n_W = -z_W: twist = sum b_i n.u_i, mid = n.(sum a_i u_i) - (c/2 - x_P) twist, c/2 - x_P = x_P
      tw.coeffRef(zdof) += -b;
      mid.coeffRef(zdof) += -a + s.ref_aft_of_le_m * b;
    }
    r.twist.push_back(tw);
    r.mid.push_back(mid);
  }
  return r;
}

struct Readout {
  Eigen::VectorXd twist_rad, mid_m;
  double tip_le_up_m = 0.0;
};

Readout readOut(const SectionRows& rows, const orni::FlexibleWingModel& flex,
                const Eigen::VectorXd& u) {
  Readout o;
  const auto ns = static_cast<Eigen::Index>(rows.twist.size());
  o.twist_rad.resize(ns);
  o.mid_m.resize(ns);
  for (Eigen::Index j = 0; j < ns; ++j) {
    o.twist_rad(j) = rows.twist[static_cast<std::size_t>(j)].dot(u);
    o.mid_m(j) = rows.mid[static_cast<std::size_t>(j)].dot(u);
  }
  const int le = flex.strips.back().section_nodes[0];
  o.tip_le_up_m = -u(orni::structure::globalDof(le, 2));
  return o;
}

struct Stats {
  double mean = 0, lo = 1e300, hi = -1e300;
  void add(double x, int n) {
    mean += x / n;
    lo = std::min(lo, x);
    hi = std::max(hi, x);
  }
};

}  // namespace

int main(int argc, char** argv) {
  using namespace orni;
  const Args args = parseArgs(argc, argv);
  try {
    VehicleDefinition def = studies::loadVehicleFile(args.vehicle);
    if (!def.model.wing.fe.nonlinear) usage("the vehicle's wing is linear (wing.fe.nonlinear)");
    if (args.shapes_given) def.model.wing.fe.static_shapes_pa = args.shapes;
    if (args.modes > 0) def.model.wing.fe.max_modes = args.modes;
    const FlightCoreModel model(def.model);
    const FlexibleWingModel& flex = *model.flexible;
    const structure::ModalWing& mw = *flex.modal;
    const OperatingPoint& point = def.design_point;
    const double period = 1.0 / point.freq_hz;
    std::printf("vehicle %s: %d vectors (%d static shapes), f_1 %.2f Hz, design point %.2f Hz, "
                "%.2f m/s, theta %.2f deg\n",
                args.vehicle.c_str(), mw.modeCount(), mw.static_shape_count, mw.frequencies_hz(0),
                point.freq_hz, point.speed_mps, point.theta_rad * 180 / kPi);

    const StripLoadOrbit rc = recordStripLoadOrbit(model, point, args.rom_cycles, args.steps);
    std::printf("reduced orbit recorded: cycle %d, %d samples\n", args.rom_cycles + 1, args.steps);

    // The full model of the same wing.
    const structure::WingStructure& ws = def.model;
    const structure::ModalWingOptions mo = structure::modalWingOptionsOf(def.model.wing.fe);
    structure::FeAssemblyOptions fo;
    fo.mass = mo.mass;
    structure::WingFeModel fe = structure::assembleWingFe(ws, mw.mesh, fo);
    structure::addSkinPretension(ws, mw.mesh, mo.support, &fe);
    const structure::DofPartition part =
        structure::makeDofPartition(fe.active, structure::wingBoundaryDofs(mw.mesh, mo.support));
    structure::FilmLaw film;
    film.compression_cap_n_per_m = args.film_cap_npm;
    const structure::VonKarmanTerms terms(
        ws, mw.mesh, structure::MemberStretch::kBothTransverse,
        args.tension_field ? structure::SkinMembrane::kTensionField : structure::SkinMembrane::kElastic,
        film);
    std::vector<Eigen::Vector3d> nodes;
    const Eigen::Vector3d p2 = mw.mesh.nodes_W_m[static_cast<std::size_t>(mw.mesh.p2_node)];
    for (const auto& x : mw.mesh.nodes_W_m) nodes.push_back(x - p2);
    structure::WingTransientOptions to;
    to.damping_s = flex.damping(0) / flex.stiffness(0);  // 2 zeta_1 / omega_1
    structure::WingTransient full(fe.stiffness, fe.mass, terms, part, nodes, to);
    const int n = fe.dofCount();
    std::printf("full model: %zu free DOFs, damping beta %.3g s\n", part.retained().size(),
                to.damping_s);

    const SectionRows rows = sectionRows(flex, n);
    const Eigen::Vector3d n_W(0, 0, -1);
    // The first-order aerodynamic correction of the difference between the full and the reduced
    // wing's section motion: quasi-steady thin-aerofoil lift, dF_n = pi rho c dy (V^2 dtheta -
    // V dw'_3/4) at the quarter chord (V = U), so that F = F_recorded - K_a (u - u_red) - C_a (u' -
    // u'_red). It vanishes on the reduced orbit (the check stays a fixed-point check) and gives
    // the full wing's departure from it the aerodynamic stiffness and damping it would meet.
    SparseMatrix k_aero(n, n), c_aero(n, n);
    {
      std::vector<Eigen::Triplet<double>> tk, tc;
      const double v_mps = point.speed_mps;
      for (std::size_t j = 0; j < flex.strips.size(); ++j) {
        const FlexibleStrip& s = flex.strips[j];
        const double chord = 4.0 * s.ref_aft_of_le_m;
        const double k = 4.0 * flex.apparent_mass_kg(static_cast<Eigen::Index>(j)) / chord;  // pi rho c dy
        const Eigen::SparseVector<double> w34 = rows.mid[j] - 0.25 * chord * rows.twist[j];
        for (std::size_t i = 0; i < 4; ++i) {
          const int row = structure::globalDof(s.section_nodes[i], 2);
          const double na = -s.force_weights[i];  // n_W.z a_i
          for (Eigen::SparseVector<double>::InnerIterator t(rows.twist[j]); t; ++t)
            tk.emplace_back(row, static_cast<int>(t.index()), -k * v_mps * v_mps * na * t.value());
          for (Eigen::SparseVector<double>::InnerIterator t(w34); t; ++t)
            tc.emplace_back(row, static_cast<int>(t.index()), k * v_mps * na * t.value());
        }
      }
      k_aero.setFromTriplets(tk.begin(), tk.end());
      c_aero.setFromTriplets(tc.begin(), tc.end());
    }

    auto loadsAt = [&](int i, Eigen::VectorXd* f, SparseMatrix* added) {
      f->setZero(n);
      std::vector<Eigen::Triplet<double>> trip;
      const auto ns = static_cast<Eigen::Index>(flex.strips.size());
      for (Eigen::Index j = 0; j < ns; ++j) {
        const FlexibleStrip& s = flex.strips[static_cast<std::size_t>(j)];
        const Eigen::Vector3d F = rc.force_W[static_cast<std::size_t>(i)].col(j);
        const double m = rc.moment_Nm[static_cast<std::size_t>(i)](j);
        for (std::size_t k = 0; k < 4; ++k)
          f->segment<3>(structure::globalDof(s.section_nodes[k], 0)) +=
              s.force_weights[k] * F + s.moment_weights[k] * m * n_W;
        const double fj = rc.separation_f[static_cast<std::size_t>(i)](j);
        const double cm = 0.5 * (1.0 + fj) * flex.apparent_mass_kg(j);
        const double ct = fj * flex.apparent_rotary_kgm2(j);
        const auto& w = rows.mid[static_cast<std::size_t>(j)];
        const auto& t = rows.twist[static_cast<std::size_t>(j)];
        for (Eigen::SparseVector<double>::InnerIterator a(w); a; ++a)
          for (Eigen::SparseVector<double>::InnerIterator b(w); b; ++b)
            trip.emplace_back(static_cast<int>(a.index()), static_cast<int>(b.index()), cm * a.value() * b.value());
        for (Eigen::SparseVector<double>::InnerIterator a(t); a; ++a)
          for (Eigen::SparseVector<double>::InnerIterator b(t); b; ++b)
            trip.emplace_back(static_cast<int>(a.index()), static_cast<int>(b.index()), ct * a.value() * b.value());
      }
      added->resize(n, n);
      added->setFromTriplets(trip.begin(), trip.end());
      *f += k_aero * (mw.mode_shapes * rc.q[static_cast<std::size_t>(i)]) +
            c_aero * (mw.mode_shapes * rc.qd[static_cast<std::size_t>(i)]);
    };
    auto frameAt = [&](double t, structure::WingTransientLoads* l) {
      const FlapState fs = flapStateAt(def.model.flapping.amplitude_rad, point.freq_hz, t);
      l->omega_x_radps = fs.phi_dot_radps;
      l->alpha_x_radps2 = fs.phi_ddot_radps2;
    };

    Eigen::VectorXd force;
    SparseMatrix added;
    structure::WingTransientLoads loads;
    loads.force = &force;
    loads.added_mass = &added;
    loads.added_stiffness = &k_aero;
    loads.added_damping = &c_aero;
    loadsAt(0, &force, &added);
    frameAt(rc.t_s[0], &loads);
    const int S = args.steps;
    const double h = period / S;
    // From rest, undeformed, the loads and the frame's motion ramped in over the first cycle
    // (smoothstep): the reduced state is not a state the full skin balances (its shape puts
    // newtons on single skin nodes of 1e-8 kg, from which Newton does not recover), and the
    // aerodynamic correction damps the start-up within a cycle.
    const Eigen::VectorXd zero = Eigen::VectorXd::Zero(n);
    {
      Eigen::VectorXd none = zero;
      structure::WingTransientLoads rest;
      rest.force = &none;
      full.setState(zero, zero, rest);
    }
    auto ramp = [&](double t_from_start) {
      const double x = std::min(1.0, t_from_start / period);
      return x * x * (3.0 - 2.0 * x);
    };
    std::vector<Readout> full_out(static_cast<std::size_t>(S) + 1), prev_out;
    full_out[0] = readOut(rows, flex, full.displacement());
    long newton = 0;
    for (int c = 0; c < args.full_cycles; ++c) {
      prev_out = full_out;
      for (int i = 1; i <= S; ++i) {
        loadsAt(i, &force, &added);
        frameAt(rc.t_s[0] + c * period + i * h, &loads);
        const double s_ramp = ramp(c * period + i * h);
        force *= s_ramp;
        loads.omega_x_radps *= s_ramp;
        loads.alpha_x_radps2 *= s_ramp;
        // A step Newton does not converge (a slack skin far from equilibrium: the start) is
        // taken again as substeps, the loads held at the step's end.
        std::function<void(double, int)> advance = [&](double dt, int depth) {
          const auto rep = full.step(dt, loads);
          newton += rep.newton_iterations;
          if (rep.converged) return;
          if (depth >= 4) {
            // Where the wing is when Newton gives up: the largest out-of-plane displacement and
            // whether a strip's load node carries it (a point load on the bare film).
            const Eigen::VectorXd u = full.displacement();
            int worst = 0;
            for (int p = 0; p < mw.mesh.nodeCount(); ++p)
              if (std::abs(u(structure::globalDof(p, 2))) > std::abs(u(structure::globalDof(worst, 2))))
                worst = p;
            std::string role = "not a load node";
            for (std::size_t j = 0; j < flex.strips.size(); ++j)
              for (std::size_t k = 0; k < 4; ++k)
                if (flex.strips[j].section_nodes[k] == worst)
                  role = "node " + std::string(1, "LQTE"[k]) + " of strip " + std::to_string(j);
            const Eigen::Vector3d& x = mw.mesh.nodes_W_m[static_cast<std::size_t>(worst)];
            std::printf("at failure: largest |w| %.2f mm at node %d (x %.1f, y %.1f mm; %s)\n",
                        std::abs(u(structure::globalDof(worst, 2))) * 1e3, worst, x.x() * 1e3,
                        x.y() * 1e3, role.c_str());
            throw std::runtime_error("full model, cycle " + std::to_string(c + 1) + " step " +
                                     std::to_string(i) + ": " + rep.message);
          }
          for (int k = 0; k < 4; ++k) advance(dt / 4, depth + 1);
        };
        advance(h, 0);
        full_out[static_cast<std::size_t>(i)] = readOut(rows, flex, full.displacement());
      }
      full_out[0] = full_out[static_cast<std::size_t>(S)];
      // Cycle-to-cycle change of the tip twist (rad, max over the samples).
      double change = 0.0;
      if (c > 0)
        for (int i = 0; i <= S; ++i)
          change = std::max(change, (full_out[static_cast<std::size_t>(i)].twist_rad -
                                     prev_out[static_cast<std::size_t>(i)].twist_rad)
                                        .cwiseAbs()
                                        .maxCoeff());
      std::printf("full cycle %d: %ld Newton iterations so far; largest twist change against the "
                  "cycle before %.3f deg\n",
                  c + 1, newton, change * 180 / kPi);
      std::fflush(stdout);
    }

    // Compare over the last cycle (samples 1..S).
    const auto ns = static_cast<Eigen::Index>(flex.strips.size());
    const Eigen::Index mid_strip = ns / 2, tip = ns - 1;
    Stats tw_r[2], tw_f[2], mid_r[2], mid_f[2], tipd_r, tipd_f;
    double d2 = 0, r2 = 0;
    std::ofstream csv;
    if (!args.csv.empty()) {
      csv.open(args.csv);
      csv << "t_s,tip_twist_reduced_deg,tip_twist_full_deg,mid_twist_reduced_deg,"
             "mid_twist_full_deg,tip_le_reduced_mm,tip_le_full_mm\n";
    }
    for (int i = 1; i <= S; ++i) {
      const Readout r = readOut(rows, flex, mw.mode_shapes * rc.q[static_cast<std::size_t>(i)]);
      const Readout& f = full_out[static_cast<std::size_t>(i)];
      const Eigen::Index idx[2] = {mid_strip, tip};
      for (int k = 0; k < 2; ++k) {
        tw_r[k].add(r.twist_rad(idx[k]) * 180 / kPi, S);
        tw_f[k].add(f.twist_rad(idx[k]) * 180 / kPi, S);
        mid_r[k].add(r.mid_m(idx[k]) * 1e3, S);
        mid_f[k].add(f.mid_m(idx[k]) * 1e3, S);
      }
      tipd_r.add(r.tip_le_up_m * 1e3, S);
      tipd_f.add(f.tip_le_up_m * 1e3, S);
      d2 += (f.twist_rad - r.twist_rad).squaredNorm();
      r2 += r.twist_rad.squaredNorm();
      if (csv)
        csv << rc.t_s[static_cast<std::size_t>(i)] << ',' << r.twist_rad(tip) * 180 / kPi << ','
            << f.twist_rad(tip) * 180 / kPi << ',' << r.twist_rad(mid_strip) * 180 / kPi << ','
            << f.twist_rad(mid_strip) * 180 / kPi << ',' << r.tip_le_up_m * 1e3 << ','
            << f.tip_le_up_m * 1e3 << '\n';
    }
    auto row = [](const char* name, const Stats& a, const Stats& b) {
      std::printf("| %s | %.2f [%.2f, %.2f] | %.2f [%.2f, %.2f] |\n", name, a.mean, a.lo, a.hi,
                  b.mean, b.lo, b.hi);
    };
    std::printf("\n| last cycle: mean [min, max] | reduced | full |\n| --- | --- | --- |\n");
    row("mid-span twist (deg)", tw_r[0], tw_f[0]);
    row("tip twist (deg)", tw_r[1], tw_f[1]);
    row("mid-span mid-chord deflection (mm)", mid_r[0], mid_f[0]);
    row("tip mid-chord deflection (mm)", mid_r[1], mid_f[1]);
    row("tip leading edge (mm, up)", tipd_r, tipd_f);
    std::printf("\nrms twist difference over all strips and samples / rms reduced twist: %.3f\n",
                std::sqrt(d2 / r2));
    return 0;
  } catch (const std::exception& e) {
    std::cerr << "orni_flapping_reference: " << e.what() << '\n';
    return 1;
  }
}
