//! `delta-stability`: the longitudinal (pitch-plane) dynamic stability of
//! aircraft after W.B. McCarter, *Note on the longitudinal stability
//! characteristics and damping in pitch of delta wings at subsonic,
//! transonic and supersonic speeds*, College of Aeronautics, 1953.

use clap::{Parser, Subcommand};
use std::process::ExitCode;

use delta_stability::cmd;

/// The exit statuses and the limits on input files, after every command's
/// help.
const AFTER_HELP: &str = "\
Exit status:
  0  success
  2  bad input: a file's content or a command-line value (the message names
     the file, line and field, or the option)
  3  a file could not be read or written: missing, not a regular file, no
     permission, a full disk, or a path through a file (the message names
     the path)
  130, 143  interrupted (SIGINT, SIGTERM): the run's temporary files removed

Input files (derivative files, configs, AVL .st files, CSV tables) are read
only from regular files (not a FIFO or a device) of at most 16 MiB. No output
may be an input (the file, or a table or .st file it names) or another output
of the same command (exit status 2); files written together (--state-space's
.json, .py and .m) are written as a set.";

/// Longitudinal dynamic stability of aircraft, after McCarter (1953).
///
/// Equation numbers refer to the report. Derivatives are in the report's
/// notation (§3): forces and moments made non-dimensional on ½ρSV, ½ρSVc̄,
/// ½ρSc̄ …; time in units of τ = m/(½ρSV); relative density μ₁ = m/(½ρSc̄);
/// pitching inertia i_B = B/(mc̄²).
#[derive(Parser)]
#[command(name = "delta-stability", version, about, long_about = None, propagate_version = true)]
#[command(after_help = AFTER_HELP)]
struct Cli {
    #[command(subcommand)]
    command: Command,
}

#[derive(Subcommand)]
enum Command {
    /// The stability quartic of a derivative set, its roots, modes and criteria.
    ///
    /// Prints the coefficients of A λ⁴ + B λ³ + C λ² + D λ + E = 0 (eqs 4–6),
    /// Routh's discriminant (§4), the four roots (units of 1/τ) and the modes:
    /// short period, phugoid, or aperiodic where a pair splits — with period,
    /// time to half (or double) amplitude, cycles to half amplitude (eq 8),
    /// damping ratio, undamped frequency and frequency parameter ω̄ (§9);
    /// then the report's one-cycle damping standard (§8, eq 41) and the
    /// MIL-F-8785C damping levels; and the mode shapes (each mode's
    /// eigenvector: |u/V|, α, q, θ with their phases relative to θ).
    ///
    /// With [dimensional] (τ = m/(½ρSV) known) the modes also come in
    /// seconds: a damp() table as MATLAB and python-control print it
    /// (eigenvalue in 1/s, ζ, ωₙ in rad/s, period, time to half or double,
    /// cycles), and the MIL-F-8785C short-period frequency requirement
    /// (§3.2.2.1.1: CAP = ω_sp²/(n/α), n/α = −z_w/C_L g/rad) beside the
    /// damping one.
    ///
    /// FILE is TOML, in the report's notation or another (see `convert --help`):
    ///
    ///   notation = "report"
    ///   [derivatives]   # x_u x_w x_wdot x_q z_u z_w z_wdot z_q m_u m_w m_wdot m_q
    ///   x_u = -0.05
    ///   ...
    ///   [flight]
    ///   c_l = 0.3       # lift coefficient of the level flight, eq (24)
    ///   mu1 = 50.0      # relative density m/(½ρSc̄)
    ///   i_b = 0.08      # pitching inertia B/(mc̄²)
    ///   [dimensional]   # optional: adds times in seconds (τ = m/(½ρSV))
    ///   V = 250.0       # m/s
    ///   rho = 0.41      # kg/m³
    ///   S = 93.0        # m²
    ///   chord = 6.6     # m, the chord of the derivatives and of μ₁
    ///   mass = 12000.0  # kg
    ///   [control]       # optional: B of --state-space, per radian of δ
    ///   name = "elevator"
    ///   C_mdelta = -1.2 # ∂C_m/∂δ; C_zdelta (or C_Ldelta) and C_xdelta default to 0
    ///
    /// The coefficients are the exact expansion of the determinant of eq (4);
    /// the report's printed eq (6) has three misprints, corrected here (see
    /// docs/errata.md). Examples: examples/*.toml.
    ///
    /// Handbook data (NASA CR-2144, Etkin & Reid, Nelson) go in as printed,
    /// with notation = "dimensional": per unit mass and inertia (the
    /// default), per force and moment (form = "per_force", with [reference]
    /// mass and I_y) or with Z_alpha, M_alpha, M_alphadot (form = "alpha",
    /// inferred from those names: U₀ times Z_w, M_w, M_ẇ); the general
    /// model det(λE − A) (eqs D1–D2, docs/dimensional.md) then gives the roots
    /// in 1/s and the modes in seconds:
    ///
    ///   notation = "dimensional"
    ///   axes = "body"     # or "stability" (required: body-axis data read as
    ///                     # stability axes give a wrong phugoid)
    ///   units = "ft"      # ft, slug, s, g = 32.174; or "si": m, kg, s, g = 9.80665
    ///   [derivatives]     # X_u X_w Z_u Z_w M_u M_w M_q required; X_wdot X_q
    ///   X_u = -0.00276    # Z_wdot Z_q M_wdot and the u̇ terms X_udot Z_udot
    ///   ...               # M_udot optional (0)
    ///   [flight]
    ///   U0 = 771.5        # trim velocity along x (ft/s or m/s); or V, alpha0
    ///   W0 = 62.07        # along z (body axes)
    ///   theta0 = 4.6      # pitch attitude, degrees (required in body axes)
    ///   g = 32.174        # optional
    ///   [reference]       # optional: the report's τ, μ₁, i_B and eq (41)
    ///   chord = 27.3      # c̄; rho, S, mass (or weight), I_y; or mu1, i_b
    ///
    /// See examples/aircraft/*.toml (five published sets, with their sources,
    /// and two of them in the other forms).
    #[command(verbatim_doc_comment)]
    Quartic(cmd::quartic::Args),
    /// The longitudinal response (§11) to an elevon step or an initial disturbance.
    ///
    /// Solved exactly from the state-space form of eqs (2) (matrix
    /// exponential of the augmented system; not a fixed-step integrator).
    /// Time t̂ is in units of τ. For a step, the CSV also carries the
    /// report's two-degree-of-freedom closed form, eqs (44)–(45).
    Response(cmd::response::Args),
    /// From a planform and flight condition to derivatives, modes and criteria.
    ///
    /// CONFIG (TOML) gives the planform (§2.2), the flight condition and the
    /// model choices; the program computes the aerodynamic coefficients (§6,
    /// documented defaults or your tables), the stiffness derivatives
    /// (eqs 9–14, 25–29), the damping derivatives of a §7 theory, then the
    /// quartic, its modes and the criteria. See examples/delta-45.toml and
    /// examples/delta-60.toml, commented. The damping theories are listed
    /// under --damping, the aerodynamic models under --aero; docs/models.md
    /// says how to choose.
    ///
    /// Example: the 45° delta at M = 0.5 by lifting-surface theory throughout
    /// (slender-wing theory gives it two real short-period roots there):
    ///
    /// delta-stability analyze examples/delta-45.toml --mach 0.5 --damping lifting-surface --aero lifting-surface
    ///
    /// The flight condition is non-dimensional (mu1, i_b, cl_m2) or
    /// physical, when the results come in seconds and rad/s too:
    ///
    ///   [flight]
    ///   mach = 0.9
    ///   cg = 0.25
    ///   units = "si"          # "si": m, kg, N; "ft": ft, slug, lbf — the planform's size too
    ///   altitude = 11000.0    # pressure altitude (geopotential), 1976 standard atmosphere
    ///   # geometric_altitude = 11019.0            # a true height instead, or
    ///   # rho = 0.3639  speed_of_sound = 295.07   # the air as given
    ///   mass = 9000.0         # or weight = … (N or lbf)
    ///   I_y = 60000.0         # pitching moment of inertia, kg·m² or slug·ft²
    ///
    /// With the planform's area S and M.A.C. c̄ they give μ₁ = m/(½ρSc̄),
    /// i_B = I_y/(mc̄²), C_L·M² = W/(½ρa²S) (eq 24) and, at the Mach
    /// number, V = M·a, C_L and τ = m/(½ρSV); the page prints them. A
    /// quantity given in both forms (mu1 and mass, say) is an error. See
    /// examples/delta-60-physical.toml.
    ///
    ///   [aircraft]            # optional
    ///   class = "IV"          # MIL-F-8785C §1.3: I, II-C, II-L, III, IV
    ///
    /// The class sets the Category C floors of the short-period frequency
    /// requirement, the only limits that depend on it: --class, else the
    /// config's class; with neither that category is not assessed, and the
    /// page says so.
    ///
    ///   [tailplane]           # optional, and/or [foreplane]: [planform]'s keys
    ///   sweep = 45.0          #   (sweep, taper, one size) and its place:
    ///   taper = 0.2
    ///   area = 16.0
    ///   x = 12.0              # apex aft of the wing's apex (negative: ahead)
    ///   z = 0.0               # height above the wing's plane
    ///   [body]                # optional: eq (43)'s forebody
    ///   length_ahead = 8.0
    ///   diameter = 1.5
    ///
    /// Their increment over the wing (the multi-surface lattice below
    /// M = 0.9, linear supersonic theory with the tail in the wing's
    /// downwash from M = 1.2, faired between) is added to the wing's lift
    /// slope, aerodynamic centre and damping; the page and --json's
    /// `configuration` give each part's share (docs/configurations.md;
    /// examples/delta-45-tailed.toml).
    ///
    /// The margins: K_n of eq (42) (−dC_m/dC_L at constant C_L·M², from
    /// the quartic's E, so with the pitching moment's change with Mach
    /// number, m_u), H_m, the neutral point h_n (where m_w = 0 at constant
    /// speed: the aerodynamic centre, a fraction of the M.A.C.) and the
    /// static margin h_n − h in % M.A.C. (JSON: criteria.margins).
    #[command(verbatim_doc_comment)]
    Analyze(cmd::analyze::Args),
    /// Convert a derivative file from one notation to another.
    ///
    /// The notations: report (this report's, after Bryant & Gates: ½ρ, chord
    /// c̄), garner (Garrick, Garner, Mangler: ρ, ¾c̄), ribner (Ribner &
    /// Malvestuto, NACA: C_Lq … per qc̄/2V), lehrian, duncan (tail arm l_t:
    /// give [parameters] lt = l_t/c̄), perkins (Perkins & Hage), american
    /// (Etkin & Reid: C_xu C_xalpha C_zu C_zalpha C_zq C_zalphadot C_mu
    /// C_malpha C_mq C_malphadot per radian and per qc̄/2V, C_W0, with
    /// [dimensional] mass, I_y, rho, V, S, chord), american_cl (the same in
    /// the C_L/C_D form, which a notation = "american" file may also be
    /// written in: C_Lalpha C_Dalpha C_Lu C_Du C_Lq C_Lalphadot C_mu C_malpha
    /// C_mq C_malphadot, optional C_Dq C_Dalphadot, and C_L, C_D in [flight];
    /// stability axes, thrust independent of speed; C_zu = −C_Lu,
    /// C_zα = −C_Lα − C_D, C_xu = −C_Du − 2C_D, C_xα = C_L − C_Dα,
    /// C_zα̇ = −C_Lα̇), avl (read only: st_file = "case.st" with
    /// [dimensional] mass, I_y, rho, V), and dimensional (per unit mass and
    /// inertia, body or stability axes: see `quartic --help`).
    ///
    /// --from dimensional --to report turns a body-axis set into stability
    /// axes by its trim incidence α₀ = atan(W0/U0) and needs a [reference]
    /// table (chord, and rho, S, mass or weight, I_y; or mu1, i_b); what the
    /// report's eq (4) cannot hold (the u̇ terms the rotation brings in, a
    /// climb angle) is left out with a warning that says how far it moves the
    /// modes. --to dimensional needs [dimensional] (V, rho, S, chord, mass);
    /// --from dimensional --to dimensional writes the set in stability axes.
    ///
    /// Every factor is derived from the authors' definitions in
    /// stability-core/specs/notation.toml and checked against the report's
    /// appendix; the appendix's misprints are listed in docs/errata.md.
    #[command(verbatim_doc_comment)]
    Convert(cmd::convert::Args),
    /// Run the note's whole study (or, with CONFIG, your design's across Mach) and write its figures, data and conclusions.
    ///
    /// The built-in cases are the note's: tailless true deltas of 45° and 60°
    /// leading-edge sweep, c.g. at h = 0.25, μ₁ = 50, Mach 0.5 to 2.0, with
    /// the variations it studies (sweep 30°–75°, c.g., μ₁ up to 400, taper),
    /// under the default `faired` damping model (one linear lifting-surface
    /// theory at the short period's own ω̄ through M = 1:
    /// docs/damping-theories.md). Writes into DIR: figNN.svg and
    /// figNN.csv under the note's figure numbers (Figs 1–38), summary.json
    /// (`delta_45`, `delta_60`: the intervals of Mach where each wing's short
    /// period diverges or takes more than one cycle to halve, the largest μ₁
    /// meeting the standard at each Mach number and the worst of them;
    /// `conclusions`: each of the note's conclusions as {claim, section,
    /// ours, reproduced, …}, swept over the unstated i_B and C_L·M²;
    /// `assumptions`) and index.html (the same conclusions with the numbers,
    /// a table of contents and the figures; its links work wherever DIR
    /// is). About 26 s on 2 cores, most of it the doublet lattice (13 s of
    /// it §10 (ours), sizing the tail the 45° delta needs; the near-sonic
    /// solutions solved ahead of time, `cargo xtask tables`). The files
    /// are written into a temporary directory beside DIR that replaces DIR
    /// only when complete, so a killed run leaves the previous report whole;
    /// DIR, if it exists, must be an earlier report or empty: everything in
    /// it a file the report's manifest (.report-manifest.json) lists,
    /// unchanged, checked when the run starts and again when DIR is
    /// replaced (else exit status 3, naming what would be lost).
    ///
    /// With CONFIG (a design-point config, as for `analyze`): that design's
    /// own report across Mach number instead — each Mach number of --mach
    /// (A:B:STEP or a list A,B,…; default 0.5:2:0.05, widened in steps of
    /// 0.05 to take in the config's own Mach number) evaluated as
    /// `analyze CONFIG --mach M` evaluates it. DIR gets index.html (the
    /// verdict across Mach number, every root judged; a table of every Mach
    /// number; the figures), the figures as SVG and CSV (cycles to half
    /// amplitude with the one-cycle line, the roots, ζ and ωₙ of both
    /// modes, their periods and times to half or double — in seconds where
    /// the flight condition is physical —, Δm_θ̇ of eq (41), the MIL-F-8785C
    /// levels and CAP, the static and manoeuvre margins and the aerodynamic
    /// centre, every coefficient and derivative), sources.csv (each
    /// coefficient's and the damping derivatives' source at each Mach
    /// number) and summary.json (each Mach number under `analyze --json`'s
    /// key names; the Mach numbers where the verdict is meets, fails,
    /// divergent), written and replaced as above. --damping, --aero and
    /// --omega-bar replace the config's model, --class sets the airplane
    /// class of the CAP levels. Example:
    ///
    ///   delta-stability report examples/delta-60-physical.toml --mach 0.6:1.8:0.05 --out my-report
    ///
    /// To see the page as a browser does: scripts/screenshot-design-report.sh
    /// (headless Chromium: chromium --headless --no-sandbox
    /// --screenshot=OUT.png --window-size=1200,3000 file://DIR/index.html).
    Report(cmd::report::Args),
    /// Design points over a Cartesian grid of Mach, sweep, c.g., μ₁ and i_B.
    ///
    /// Each range is A:B:STEP (inclusive), a list A,B,… or a single value,
    /// for every axis; those not given
    /// come from CONFIG (see `analyze --help`). Points are evaluated in
    /// parallel; OUT (.csv or .json) is written atomically — a killed run
    /// leaves no half-written file (its temporary file beside OUT,
    /// .delta-stability-PID-XXXXXX, is removed on SIGINT or SIGTERM, or by a
    /// later run once stale). A grid whose file would not fit in the free
    /// space of OUT's file system (or the file-size limit) is refused before
    /// it is written, with the estimate (bytes per row, measured on the
    /// first rows, × rows). Columns: the grid values, stable (Routh),
    /// verdict (the one-cycle standard: meets, fails, divergent), the short
    /// period's root, cycles to half amplitude, damping ratio and ω̄, the
    /// phugoid's root, m_θ̇ and Δm_θ̇ (eq 41), the phugoid's ζ and period,
    /// the MIL-F-8785C levels, the four roots, k_n (eq 42's static margin
    /// K_n = −dC_m/dC_L at constant C_L·M², from the quartic's E: it
    /// includes the pitching moment's change with Mach number, m_u),
    /// neutral_point (h_n, where m_w = 0 at constant speed — the
    /// aerodynamic centre H₀ — as a fraction of the M.A.C.) and
    /// static_margin_pct (h_n − h, % M.A.C.; positive: stable in
    /// incidence), and an error for points outside a theory's validity.
    /// Roots are in units of 1/τ, τ = m/(½ρSV).
    /// The damping theory and aerodynamic model are CONFIG's unless --damping
    /// or --aero replace them (listed in `analyze --help`); the lifting
    /// surface is solved once per sweep and Mach number, whatever the c.g.,
    /// μ₁ and i_B.
    ///
    /// With a physical flight condition in CONFIG (units, altitude, mass,
    /// I_y: see `analyze --help`), μ₁, i_B and C_L·M² follow from it and each
    /// point's planform (the root chord is held, so they change with
    /// --sweep; --mu1 and --ib are refused), and V = M·a, C_L and τ from
    /// each Mach number: at a fixed altitude and weight C_L·M² is constant
    /// (eq 24), so C_L ∝ 1/M² and τ ∝ 1/M. --altitude (pressure altitude),
    /// --mass and --iy then vary the condition itself, in CONFIG's units:
    /// each point's μ₁, i_B, C_L·M² and speed of sound from its altitude,
    /// mass and I_y, as `analyze` computes them for CONFIG edited to them
    /// (without a physical condition they are refused). The rows then carry
    /// altitude, mass and I_y after i_b, and also v_m_s,
    /// c_l, tau_s and the modes in seconds (sp_re_s, sp_im_s,
    /// sp_natural_frequency_rad_s, sp_period_s, ph_re_s, ph_im_s).
    ///
    /// Example: the 60° delta from Mach 0.5 to 2, c.g. 0.20 to 0.30, μ₁ 50 to
    /// 450, 31 × 11 × 5 points:
    ///
    /// delta-stability sweep examples/delta-60.toml --mach 0.5:2:0.05 --cg 0.2:0.3:0.01 --mu1 50:450:100 -o sweep.csv
    Sweep(cmd::sweep::Args),
    /// The smallest tailplane (or foreplane) that meets the one-cycle standard across Mach.
    ///
    /// The note's Fig 33 shows "the need of a tailplane" for the 45° delta
    /// in 0.97 < M < 1.5; this finds how big. CONFIG's [tailplane] (or, with
    /// --surface foreplane, its [foreplane]) is the family: its sweep,
    /// taper, aspect ratio and apex x (and height z) are held and its area
    /// S_T varied, every length scaled by √(S_T/S_T,given). The answer is
    /// the smallest S_T at which the design point meets §8's standard — the
    /// short period halves within one cycle, every root judged (no mode
    /// grows) — at every Mach number of --mach, each evaluated as `analyze
    /// CONFIG --mach M` would (the config's damping model, tables and flight
    /// condition; --damping, --aero, --omega-bar, --datcom replace them),
    /// but for the doublet lattice's harmonic solutions, interpolated between
    /// fixed frequencies as `sweep` does (within 0.3 % of direct solves,
    /// below the lattice's own error: docs/damping-theories.md).
    ///
    /// Printed: the area, its ratio to yours, the tail volume
    /// V̄_T = S_T·l_T/(S·c̄) (l_T from the c.g. to the surface's M.A.C.
    /// quarter chord; negative for a foreplane) and the verdict and cycles
    /// to half amplitude at each Mach number; --json the same as one object.
    ///
    /// The search: the wing alone first (no surface needed?), then areas
    /// spaced geometrically (×1.33) from 1/1000 of the limit or of the
    /// wing's area, whichever is smaller, to the limit (the wing's area: 25
    /// areas; or --max-area, at most 1e9), then bisection to 0.1 % between the
    /// last that fails and the first that meets. The verdict need not be
    /// monotone in area (a bigger tail moves the neutral point aft and
    /// stiffens the short period as it damps it): the scan finds the first
    /// meeting area on its grid, and a window narrower than one scan step
    /// (×1.33) can be missed. When no area up to the limit meets, it says so
    /// and prints the verdicts at the limit. A Mach number with no result
    /// (outside a theory) counts as not meeting, and its reason is printed.
    /// An area's trial stops at its first failing Mach number: a search
    /// costs about one design point per failing area.
    ///
    ///   delta-stability size-tail examples/delta-45-tailed.toml --mach 1.2:2.0:0.1
    ///
    /// The configuration theory: docs/configurations.md.
    #[command(verbatim_doc_comment)]
    SizeTail(cmd::size_tail::Args),
    /// How each mode's root moves with each derivative: dλ/dp for every input.
    ///
    /// For each mode (short period, phugoid, aperiodic roots) and each of
    /// the fifteen quartic inputs p (x_u … m_q, c_l, mu1, i_b, report
    /// notation §3), the exact derivative of the root λ = r + is:
    /// dλ/dp = −(∂P/∂p)(λ)/P′(λ), by implicit differentiation of the quartic
    /// P(λ) = Aλ⁴ + … + E = 0 with the generated exact gradient of its
    /// coefficients (no finite differences). The table gives ∂r/∂p and ∂s/∂p
    /// (1/τ per unit of p; in brackets 1/s when [dimensional] gives τ, with
    /// τ held fixed), ∂ζ/∂p, ∂(cycles to half amplitude)/∂p, and
    /// p·∂r/∂p — the first-order change of the damping r if p doubled, by
    /// which the inputs are ranked: the derivative at the top drives the
    /// mode's damping most (the report's §7, §8 and §10 question). A
    /// multiple root has no derivative and says so.
    ///
    /// FILE is a derivative file, as for `quartic`.
    Sensitivity(cmd::sensitivity::Args),
    /// The probability of meeting the standard when the inputs are uncertain.
    ///
    /// CONFIG's [uncertainty] table gives a distribution for any input —
    /// i_b, mu1, cl_m2, cg; altitude, mass, I_y of a physical [flight];
    /// any derivative x_u … m_q as a multiplicative or additive error —
    /// correlations between them, and damping theories with weights:
    ///
    ///   [uncertainty.i_b]
    ///   dist = "normal"          # normal, lognormal, uniform, triangular, samples
    ///   relative_sd = 0.1        # or sd; mean defaults to the config's value
    ///   [uncertainty.m_q]
    ///   error = "multiplicative" # the default for derivatives; or additive
    ///   dist = "uniform"
    ///   low = 0.8
    ///   high = 1.2
    ///   [uncertainty.model]
    ///   damping = ["faired", "faired-slender"]
    ///   weights = [0.7, 0.3]
    ///   [uncertainty]
    ///   correlation = [{ between = ["i_b", "m_q"], rho = 0.3 }]
    ///   sampling = "sobol"       # Owen-scrambled Sobol′ points; default random
    ///
    /// (lognormal: median or mu, and sigma, of ln x; uniform: low, high;
    /// triangular: low, mode, high; samples: values = [...] or file =
    /// "x.csv", one number a line). At each Mach number: the probability
    /// of meeting the §8 one-cycle standard, of the overall verdicts (meets,
    /// fails, divergent) and of each MIL-F-8785C level, with 95 % Wilson
    /// intervals; the quantiles of cycles to half amplitude and ζ; with
    /// --sobol, the first-order and total Sobol indices of every input for
    /// Δm_θ̇ (eq 41) and ζ. A seed gives the same bits on any number of
    /// threads. See docs/uncertainty.md.
    ///
    /// delta-stability uncertainty examples/delta-60-uncertain.toml --mach 0.6:1.6:0.2 --samples 20000 --sobol -o u.csv
    #[command(verbatim_doc_comment)]
    Uncertainty(cmd::uncertainty::Args),
}

fn main() -> ExitCode {
    // first, before any thread starts: SIGINT and SIGTERM remove this
    // run's temporary files and directories before it exits
    delta_stability::output::remove_temporaries_on_signals();
    let cli = Cli::parse();
    // the note's wings' Mach box and near-sonic solutions, solved ahead of
    // time (`cargo xtask tables`), into the store: a cache, checked by the
    // solvers' fingerprints (a stale file is refused whole and every
    // solution solved afresh; `report` says so)
    let _ = stability_study::study::preload();
    let result = match cli.command {
        Command::Quartic(a) => cmd::quartic::run(&a),
        Command::Sensitivity(a) => cmd::sensitivity::run(&a),
        Command::Report(a) => cmd::report::run(&a),
        Command::Sweep(a) => cmd::sweep::run(&a),
        Command::SizeTail(a) => cmd::size_tail::run(&a),
        Command::Convert(a) => cmd::convert::run(&a),
        Command::Analyze(a) => cmd::analyze::run(&a),
        Command::Response(a) => cmd::response::run(&a),
        Command::Uncertainty(a) => cmd::uncertainty::run(&a),
    };
    match result {
        Ok(()) => ExitCode::SUCCESS,
        Err(e) => {
            delta_stability::output::warn(&format!("error: {e}"));
            ExitCode::from(e.status())
        }
    }
}
