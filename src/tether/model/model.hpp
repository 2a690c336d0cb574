#pragma once
/// \file The analysis model as read from a deck: plain data, no algorithms.
///
/// Nodes and elements are stored densely and referenced by *index*; the user's
/// labels (ids) are kept beside them for messages and output. Set, material and
/// amplitude names are stored upper-case (ABAQUS names are case-insensitive).
/// Every entry remembers where in the deck it was defined so later checks can
/// report file:line.

#include <Eigen/Core>
#include <map>
#include <optional>
#include <string>
#include <unordered_map>
#include <vector>

#include "tether/core/error.hpp"
#include "tether/model/body_load.hpp"
#include "tether/model/dialect.hpp"
#include "tether/model/constraint_data.hpp"
#include "tether/model/contact_data.hpp"
#include "tether/model/element_type.hpp"
#include "tether/model/label_map.hpp"
#include "tether/model/part_instance.hpp"
#include "tether/model/temperature_data.hpp"
#include "tether/model/pretension_section.hpp"

namespace tether {

/// A deck line kept in 8 bytes: an index into Model::source_files and the
/// 1-based line number. Model::location() turns it into the SourceLocation
/// (file:line) that messages print. For what there are many of (elements),
/// where a SourceLocation (a file name string each, 40 bytes) is too much.
struct DeckLine {
  int file = -1;  ///< index into Model::source_files; -1: no file (location() gives an empty name)
  int line = 0;   ///< 1-based; 0: unknown
};

/// A continuum element of the mesh.
/// (64 bytes, one per mesh element: the two ints side by side, the deck line as a DeckLine.)
struct Element {
  int id = 0;                ///< user label
  int section = -1;          ///< index into Model::sections, -1 until assigned
  ElementType type;          ///< from the catalogue
  std::vector<int> nodes;    ///< node indices (not labels), ABAQUS order
  DeckLine where;            ///< the data line that defined it (Model::location(where): file:line)
};

/// An element face (edge in 2D), ABAQUS face id S1..S4 stored 0-based.
struct ElementFace {
  int element = 0;  ///< element index
  int face = 0;     ///< 0 = S1, 1 = S2, ...
};

/// `*SURFACE`: element faces (TYPE=ELEMENT) or nodes (TYPE=NODE).
struct Surface {
  enum class Kind { ElementFaces, Nodes };
  std::string name;
  Kind kind = Kind::ElementFaces;
  std::vector<ElementFace> faces;  ///< for ElementFaces
  std::vector<int> nodes;          ///< node indices, for Nodes (sorted, unique)
  /// For Nodes: the area of each node [length^2] (parallel to `nodes`), the
  /// second field of its data line as in ABAQUS, 1 when omitted. A node-based
  /// slave surface's contact pressure is its force divided by this area.
  std::vector<double> node_areas;
  SourceLocation where;
};

/// `*MATERIAL` with its sub-options. Exactly one of elastic / neo_hooke is set
/// for a usable solid material.
struct MaterialData {
  std::string name;
  struct Elastic {
    double young = 0;    ///< E [stress] (of the first row when temperature-dependent)
    double poisson = 0;  ///< nu [-], -1 < nu < 0.5 (of the first row)
    /// Temperature-dependent `*ELASTIC` (two or more rows): E, nu and the
    /// temperature of each row, temperatures strictly increasing; empty for
    /// one row. Interpolated linearly, constant beyond the first and last rows.
    std::vector<double> table_young, table_poisson, table_temperature;
  };
  /// `*EXPANSION` (isotropic): the secant (total) coefficient alpha(T) about
  /// the reference temperature ZERO, thermal strain
  /// alpha(T) (T - zero) - alpha(T_I) (T_I - zero) with T_I the initial temperature.
  struct Expansion {
    std::vector<double> alpha;        ///< [1/temperature], one per row
    std::vector<double> temperature;  ///< per row, strictly increasing; empty for one row without temperature
    double zero = 0;                  ///< ZERO= [temperature] (ABAQUS's and CalculiX's default 0)
    SourceLocation where;             ///< the *EXPANSION line
  };
  std::optional<Expansion> expansion;
  struct NeoHooke {
    double c10 = 0;  ///< C10 = mu/2 [stress]
    double d1 = 0;   ///< D1 = 2/K [1/stress]; 0 means incompressible (refused)
  };
  std::optional<Elastic> elastic;
  std::optional<NeoHooke> neo_hooke;
  /// `*PLASTIC`: von Mises plasticity, true yield stress against equivalent
  /// plastic strain, piecewise linear and constant beyond the last row.
  struct Plastic {
    enum class Hardening { Isotropic, Kinematic, Combined };
    Hardening hardening = Hardening::Isotropic;
    std::vector<double> yield_stress;    ///< [stress], > 0, one per row
    std::vector<double> plastic_strain;  ///< [-], 0 first, strictly increasing (within each temperature)
    /// The temperature column, one per row [temperature]; empty without it.
    /// Rows of one temperature form one curve (plastic strain 0 first);
    /// temperatures increase from curve to curve.
    std::vector<double> temperature;
    SourceLocation where;                ///< the *PLASTIC line
    /// `*CYCLIC HARDENING` (HARDENING=COMBINED): the yield stress against
    /// PEEQ (and temperature), same rules as the *PLASTIC rows; empty when not given.
    std::vector<double> cyclic_yield_stress, cyclic_plastic_strain, cyclic_temperature;
    SourceLocation cyclic_where;         ///< the *CYCLIC HARDENING line
  };
  std::optional<Plastic> plastic;
  /// `*USER MATERIAL`: an ABAQUS UMAT loaded from a shared library.
  struct User {
    std::string library;             ///< LIBRARY= as written (a path with '/' is relative to the working directory)
    std::string symbol;              ///< SYMBOL= ("" = umat_, gfortran's name of SUBROUTINE UMAT)
    std::vector<double> constants;   ///< PROPS
    SourceLocation where;            ///< the *USER MATERIAL line
  };
  std::optional<User> user;
  std::optional<int> depvar;         ///< `*DEPVAR`: NSTATV, the UMAT's number of state variables
  SourceLocation depvar_where;       ///< the *DEPVAR line
  std::optional<double> density;  ///< [mass/volume]
  /// `*DAMPING, ALPHA=, BETA=` (ABAQUS's Rayleigh damping of the material):
  /// in dynamic steps the element's damping matrix is C = alpha M + beta K.
  struct Damping {
    double alpha = 0;  ///< mass-proportional factor [1/time]
    double beta = 0;   ///< stiffness-proportional factor [time]
    SourceLocation where;
  };
  std::optional<Damping> damping;
  SourceLocation where;

  /// A stiffness of the material [stress] for scaling and comparing bodies:
  /// E, or 6 C10 (= 3μ, E of the incompressible small-strain limit) for
  /// neo-Hooke; 0 with neither.
  [[nodiscard]] double modulus() const {
    if (elastic) return elastic->young;
    if (neo_hooke) return 6 * neo_hooke->c10;
    return 0;
  }
};

/// `*SOLID SECTION`.
struct SolidSection {
  std::string elset;     ///< element set name (upper case)
  int material = -1;     ///< index into Model::materials
  double thickness = 1;  ///< out-of-plane thickness (plane strain/stress); ignored for CAX
  SourceLocation where;
};

/// `*AMPLITUDE` (tabular, piecewise linear, constant beyond the ends).
struct Amplitude {
  std::string name;
  bool total_time = false;               ///< TIME=TOTAL TIME (default STEP TIME)
  std::vector<double> times, values;     ///< strictly increasing times
  SourceLocation where;
};

/// One prescribed displacement component: u(node, dof) = value (scaled by the
/// amplitude, or ramped from the value at the start of the step when there is none).
struct Prescribed {
  int node = 0;               ///< node index
  int dof = 0;                ///< 0 = x (or r), 1 = y (or z), 2 = in-plane rotation (ABAQUS dof 6)
  double value = 0;           ///< [length] ([rad] for a rotation); a velocity [length/time] when `velocity`
  int amplitude = -1;         ///< index into Model::amplitudes or -1
  SourceLocation where;
  /// *BOUNDARY, TYPE=VELOCITY: `value` (times the amplitude) is the dof's
  /// velocity; its displacement is the time integral from the step's start.
  bool velocity = false;
  /// `*BOUNDARY, FIXED`: held at its value at the start of the step (`value`
  /// and `amplitude` unused).
  bool fixed = false;
};

/// `*CLOAD` line: concentrated force on one node component.
struct ConcentratedLoad {
  int node = 0;
  int dof = 0;                ///< 0 or 1; 2 = moment about z (ABAQUS dof 6)
  double magnitude = 0;       ///< [force] ([force*length] for a moment); for CAX: total over 2*pi
  int amplitude = -1;
  SourceLocation where;
};

/// `*DLOAD` / `*DSLOAD` pressure on an element face; positive pushes into the
/// face. Follows the deformed face under NLGEOM.
struct PressureLoad {
  ElementFace face;
  double magnitude = 0;       ///< [force/area]
  int amplitude = -1;
  SourceLocation where;
};

/// Convergence controls (`*CONTROLS, PARAMETERS=FIELD` and `TIME INCREMENTATION`),
/// with ABAQUS's defaults.
struct Controls {
  double residual_tolerance = 5e-3;     ///< R_n^alpha: |r|_inf <= tol * average force
  double correction_tolerance = 1e-2;   ///< C_n^alpha: |du|_inf <= tol * largest incremental displacement
  double zero_force_tolerance = 1e-8;   ///< eps^alpha: average force below this counts as zero
  int max_iterations = 16;              ///< iterations per attempt before a cut-back (I_A-like)
  int max_cutbacks = 5;                 ///< consecutive cut-backs before the step is abandoned
  double cutback_factor = 0.25;         ///< D_f
  double growth_factor = 1.5;           ///< increase after two easy increments
  int easy_iterations = 5;              ///< "easy" means converged in at most this many iterations
  bool line_search = false;             ///< backtracking line search on the residual norm
};

/// `*NODE PRINT`, `*EL PRINT`, `*NODE FILE`, `*EL FILE` request.
struct OutputRequest {
  enum class Kind { NodePrint, ElementPrint, NodeFile, ElementFile, ContactPrint, ContactFile };
  Kind kind = Kind::NodePrint;
  std::string set;                    ///< NSET/ELSET name (upper case); empty = all
  std::vector<std::string> variables; ///< U, RF, S, E, ... (upper case)
  int frequency = 1;                  ///< every n-th increment (0 = none); last always written
  bool totals = false;                ///< TOTALS=YES/ONLY
  bool totals_only = false;           ///< TOTALS=ONLY
  SourceLocation where;
  // Set after `where`, so that positional initializers of the fields above keep their meaning.
  /// NUMBER INTERVAL= (`*OUTPUT`): write at the ends of this many equal
  /// intervals of the step; 0 = not given (FREQUENCY or TIME INTERVAL rules).
  int number_interval = 0;
  /// TIME INTERVAL= (`*OUTPUT`) [time]: write at every multiple of it; 0 = not given.
  double time_interval = 0;
  /// TIME MARKS=YES: static and implicit increments are shortened to end on
  /// the interval marks (NO, the default: the first increment ending at or
  /// after a mark writes). Explicit steps always end a report on the marks.
  bool time_marks = false;
  /// FREQUENCY, NUMBER INTERVAL or TIME INTERVAL was written (else the
  /// procedure's default applies: see explicit steps in docs/keywords.md).
  bool schedule_given = false;
};

/// The procedure of a step.
enum class StepProcedure {
  Static,           ///< `*STATIC`
  ImplicitDynamic,  ///< `*DYNAMIC` (HHT-alpha, Newton)
  ExplicitDynamic,  ///< `*DYNAMIC, EXPLICIT` (central difference, lumped mass)
};

/// Data of a `*DYNAMIC` step.
struct DynamicData {
  /// HHT's alpha in [-1/3, 0] (ALPHA=; ABAQUS's and CalculiX's default -0.05);
  /// Newmark's beta = (1 - alpha)^2 / 4 and gamma = 1/2 - alpha follow from it.
  double alpha = -0.05;
  /// Mass matrix: lumped (MASS=LUMPED, and always for EXPLICIT) or consistent.
  bool lumped_mass = false;
  /// Implicit: contact-surface nodes lose their mass to their elements' other
  /// nodes (impact stabilisation; CONTACT MASS=REDISTRIBUTED, the default, or KEPT).
  bool redistribute_contact_mass = true;
  /// Implicit: ABAQUS's HAFTOL [force], the largest half-increment residual
  /// accepted; it turns on automatic incrementation. 0: none (the increment
  /// never grows past the initial one).
  double half_increment_tolerance = 0;
};

/// `*STEP` ... `*END STEP` with one procedure (`*STATIC` or `*DYNAMIC`).
struct Step {
  std::string name;
  StepProcedure procedure = StepProcedure::Static;
  DynamicData dynamic;                ///< for the dynamic procedures
  /// Loads and prescribed values without an amplitude: ramped over the step
  /// from their previous values (AMPLITUDE=RAMP, the default of static steps)
  /// or applied at the step's start and held (AMPLITUDE=STEP, the default of
  /// dynamic steps).
  bool ramp_loads = true;
  /// Prescribed displacements (*BOUNDARY, TYPE=DISPLACEMENT) without an
  /// amplitude: ramped over the step, or held from its start. ABAQUS/Standard
  /// always ramps them, in dynamic steps too; ABAQUS/Explicit and CalculiX
  /// follow the step's default (held in dynamic steps) — set by the reader
  /// from the dialect (docs/keywords.md, Dialects).
  bool ramp_prescribed = true;
  bool nlgeom = false;
  /// EXTRAPOLATION=LINEAR (default, as ABAQUS/Standard) or NO: a static
  /// increment starts from the step's last converged increment scaled to
  /// its size, or from the converged state (docs/theory/newton.md).
  bool extrapolate = true;
  int max_increments = 100;           ///< INC=
  double initial_increment = 1;       ///< first increment [time]; 0 = the whole period
  double period = 1;                  ///< step time period
  double min_increment = 0;           ///< 0 = default (1e-5 * period)
  double max_increment = 0;           ///< 0 = no limit (period)
  bool direct = false;                ///< fixed increments, no cut-back
  /// Step times increments must end on (sorted, within (0, period]): the
  /// output marks of TIME MARKS=YES requests, or an explicit step's reports.
  std::vector<double> time_points;
  Controls controls;
  /// Complete lists in force during this step (OP=MOD/NEW already resolved by
  /// the reader; model-level *BOUNDARY included).
  std::vector<Prescribed> boundary;
  std::vector<ConcentratedLoad> cloads;
  std::vector<PressureLoad> pressures;
  std::vector<BodyLoad> body_loads;  ///< *DLOAD GRAV / CENTRIF
  StepTemperatureData temperatures;  ///< *TEMPERATURE given in this step
  std::vector<OutputRequest> outputs;
  /// `*RESTART, WRITE, FREQUENCY=n` in force: the restart state is written
  /// after every n-th converged increment and at the end of the step; 0 = not written.
  int restart_frequency = 0;
  SourceLocation where;
};

/// `*RESTART, READ` (model data): continue from a saved state.
struct RestartRead {
  std::string file;       ///< FILE= as written (relative to the deck's directory); empty: from the command line
  int step = 0;           ///< STEP=: the state must be from this step (0 = any)
  int increment = 0;      ///< INC=: ... and this increment of it (0 = any)
  SourceLocation where;
};

/// The whole model.
struct Model {
  std::string heading;
  std::string deck_path;  ///< path of the main deck
  Dialect dialect = Dialect::Abaqus;  ///< the meaning the deck was read with

  // --- mesh ---
  std::vector<int> node_ids;              ///< label of node i
  std::vector<Eigen::Vector2d> coords;    ///< reference coordinates of node i (x,y) or (r,z)
  LabelMap node_index;                    ///< label -> index
  std::vector<Element> elements;
  LabelMap element_index;                 ///< label -> index
  /// ABAQUS/CAE part instances (empty for a flat deck): which labels belong to
  /// which instance, for naming them `INSTANCE.label` (label_text()).
  std::vector<PartInstance> instances;

  // --- named things (keys upper case) ---
  std::map<std::string, std::vector<int>> node_sets;     ///< node indices, sorted, unique
  std::map<std::string, std::vector<int>> element_sets;  ///< element indices, sorted, unique
  std::map<std::string, Surface> surfaces;
  std::vector<MaterialData> materials;
  std::vector<SolidSection> sections;
  std::vector<Amplitude> amplitudes;
  std::vector<ConstraintData> constraints;  ///< *EQUATION, *MPC, *CONSTRAINT (model data)
  std::vector<SurfaceInteraction> interactions;  ///< *SURFACE INTERACTION
  std::vector<ContactPairData> contact_pairs;    ///< *CONTACT PAIR
  /// `*PRE-TENSION SECTION`s; their equations are in `constraints` (Kind::Linear).
  std::vector<PretensionSection> pretension_sections;

  std::vector<Step> steps;
  /// `*INITIAL CONDITIONS, TYPE=VELOCITY`: (node index, component 0/1, value [length/time]).
  struct InitialVelocity {
    int node = 0;
    int dof = 0;
    double value = 0;
    SourceLocation where;
  };
  std::vector<InitialVelocity> initial_velocities;
  /// `*INITIAL CONDITIONS, TYPE=TEMPERATURE` (one entry per node, the last given wins).
  std::vector<NodeTemperature> initial_temperatures;
  /// True when the deck gives temperatures (initial or in a step).
  [[nodiscard]] bool has_temperatures() const {
    if (!initial_temperatures.empty()) return true;
    for (const Step& s : steps)
      if (!s.temperatures.values.empty() || s.temperatures.reset) return true;
    return false;
  }
  std::optional<RestartRead> restart_read;  ///< `*RESTART, READ`, when given

  /// The files that DeckLine::file indexes (the deck and its *INCLUDEs, named
  /// as their SourceLocations name them), each once.
  std::vector<std::string> source_files;

  [[nodiscard]] int n_nodes() const { return static_cast<int>(coords.size()); }
  [[nodiscard]] int n_elements() const { return static_cast<int>(elements.size()); }

  /// file:line of a DeckLine: the same SourceLocation as the one deck_line()
  /// was given (file "" and the line for a DeckLine without a file).
  [[nodiscard]] SourceLocation location(const DeckLine& at) const {
    if (at.file < 0) return {std::string(), at.line};
    return {source_files[static_cast<std::size_t>(at.file)], at.line};
  }
  /// `where` as a DeckLine; its file is added to source_files when new (the
  /// search starts at the last file added: consecutive lines share a file).
  DeckLine deck_line(const SourceLocation& where) {
    for (std::size_t k = source_files.size(); k-- > 0;)
      if (source_files[k] == where.file) return {static_cast<int>(k), where.line};
    source_files.push_back(where.file);
    return {static_cast<int>(source_files.size() - 1), where.line};
  }
};

}  // namespace tether
