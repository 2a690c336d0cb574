// The declaration table of every keyword the reader knows. Adding a keyword:
// one entry here + one handler in the matching *_keywords.cpp file.
#include "tether/io/keyword_table.hpp"

#include <stdexcept>

#include "tether/io/keyword_handlers.hpp"

namespace tether::deck {

namespace {

using PT = ParameterType;

ParameterSpec flag(std::string_view name, std::string_view description) {
  return {name, PT::Flag, "", {}, false, "", description};
}
ParameterSpec name(std::string_view name, std::string_view description, bool required = false) {
  return {name, PT::Name, "", {}, required, "", description};
}
ParameterSpec integer(std::string_view name, std::string_view default_value, std::string_view description) {
  return {name, PT::Integer, default_value, {}, false, "", description};
}
ParameterSpec choice(std::string_view name, std::string_view default_value,
                     std::vector<std::string_view> choices, std::string_view description,
                     std::string_view flag_value = "") {
  return {name, PT::Choice, default_value, std::move(choices), false, flag_value, description};
}

ParameterSpec real(std::string_view name, std::string_view default_value, std::string_view description) {
  return {name, PT::Real, default_value, {}, false, "", description};
}

/// tether's extension parameters choosing how a constraint is enforced.
std::vector<ParameterSpec> enforcement_params(std::vector<ParameterSpec> more) {
  std::vector<ParameterSpec> p = {
      name("NAME", "Name used in messages and in the multiplier output (tether extension)."),
      choice("ENFORCEMENT", "LAGRANGE", {"LAGRANGE", "PENALTY", "AUGMENTED", "ELIMINATION"},
             "tether extension: Lagrange multipliers (exact; regularised with EPSILON), PENALTY (needs PENALTY=), "
             "AUGMENTED Lagrangian (penalty plus Uzawa updates until |f| <= TOLERANCE) or ELIMINATION (linear "
             "constraints only)."),
      real("EPSILON", "0", "Regularisation: enforce f - EPSILON*lambda = 0 (LAGRANGE only)."),
      real("PENALTY", "", "Penalty stiffness rho for PENALTY and AUGMENTED (force per unit of f)."),
      real("TOLERANCE", "0", "AUGMENTED: stop the Uzawa updates when |f| is below this (0: 1e-8 times the model "
                             "size)."),
  };
  for (auto& m : more) p.push_back(std::move(m));
  return p;
}

ParameterSpec amplitude_param() {
  return name("AMPLITUDE", "Amplitude scaling the values over the step; without it the value is ramped "
                           "linearly over the step from the previous step's value.");
}
ParameterSpec op_param() {
  return choice("OP", "MOD", {"MOD", "NEW"},
                "MOD: add to / replace entries with the same node and dof (or face); NEW (in a step): "
                "first remove all entries of this kind inherited from model data and earlier steps.");
}
ParameterSpec frequency_param() {
  return integer("FREQUENCY", "1", "Write every n-th increment (0: never); the last increment of the step "
                                   "is always written. In *DYNAMIC, EXPLICIT steps n counts explicit increments "
                                   "(as in ABAQUS/Explicit and CalculiX); without FREQUENCY an explicit step "
                                   "writes at 20 equal intervals to the result files and 200 to the .dat (abaqus "
                                   "dialect) or at every explicit increment (calculix dialect).");
}

std::vector<KeywordSpec> build_table() {
  constexpr unsigned kAnyStep = kStep;
  constexpr std::string_view kLater = "planned for a later version of tether";
  return {
      // --- lexer ---
      {"INCLUDE", kModelData | kMaterial | kInteraction | kStep | kBetweenSteps,
       "Reads another file in place of this line (relative to the including file).", "",
       {{"INPUT", PT::Text, "", {}, true, "", "Path of the file to read."}}, nullptr, ""},
      // --- ABAQUS/CAE structure (flattened before the keywords are read: assembly_flattening.hpp) ---
      {"PART", kModelData,
       "ABAQUS/CAE: starts a part; its *NODE, *ELEMENT, *NSET, *ELSET, *SURFACE and *SOLID SECTION lines are "
       "copied into each *INSTANCE of it, with set and surface names qualified by the instance "
       "(`Part-1-1.Set-1`). An instance keeps the part's node and element labels when no earlier instance uses "
       "them; otherwise they are all moved by one round offset (10, 100, ...) inside tether, and messages and "
       "the .dat rows of a set within one instance name them as the user knows them (`Upper-1.3`, or the part's "
       "label under the set's header). Assembly and step data may name a node or element `Instance.label`.",
       "", {name("NAME", "Name of the part.", true)}, nullptr, ""},
      {"END PART", kModelData, "ABAQUS/CAE: ends a part.", "", {}, nullptr, ""},
      {"ASSEMBLY", kModelData, "ABAQUS/CAE: starts the assembly of part instances.", "",
       {name("NAME", "Name of the assembly (not used).")}, nullptr, ""},
      {"INSTANCE", kModelData,
       "ABAQUS/CAE: an instance of a part, placed by its translation and then its rotation.",
       "optional `dx, dy, dz` (translation; dz must be 0), then optional `ax, ay, az, bx, by, bz, angle` "
       "(rotation by angle degrees about the axis from a to b, which must be along z)",
       {name("NAME", "Name of the instance: qualifies the part's set and surface names.", true),
        name("PART", "The part it is an instance of.", true)},
       nullptr, ""},
      {"END INSTANCE", kModelData, "ABAQUS/CAE: ends an instance.", "", {}, nullptr, ""},
      {"END ASSEMBLY", kModelData, "ABAQUS/CAE: ends the assembly.", "", {}, nullptr, ""},
      {"PREPRINT", kModelData, "ABAQUS printing of the input to its .dat file: accepted and ignored.", "",
       {choice("ECHO", "NO", {"YES", "NO"}, "Ignored."), choice("MODEL", "NO", {"YES", "NO"}, "Ignored."),
        choice("HISTORY", "NO", {"YES", "NO"}, "Ignored."), choice("CONTACT", "NO", {"YES", "NO"}, "Ignored.")},
       handle_preprint, ""},
      // --- model data: mesh ---
      {"HEADING", kModelData, "Title of the analysis; the data lines are kept as the model heading.",
       "free text lines", {}, handle_heading, ""},
      {"NODE", kModelData, "Defines nodes by label and coordinates.",
       "`label, x, y[, z[, nx, ny, nz]]` ((r, z) for axisymmetric models; a non-zero z is ignored with a "
       "warning; empty or missing coordinates are 0, as in CalculiX; fields 5-7, ABAQUS's normal direction for "
       "shells and beams, are ignored with a warning, as CalculiX ignores them)",
       {name("NSET", "Also add the nodes to this node set.")}, handle_node, ""},
      {"ELEMENT", kModelData,
       "Defines 2D continuum elements of one type, or line elements (T2D2/T2D3/T3D2/T3D3, as Gmsh writes "
       "physical curves), which carry no stiffness: they only name the faces of the solid elements they lie on "
       "in *SURFACE, TYPE=ELEMENT (a line element in any other place is an error).",
       "`label, n1, n2, ...` in ABAQUS node order; a line ending with ',' continues on the next",
       {name("TYPE", "Element type: CPE3/4/6/8/8R, CPS3/4/6/8/8R, CAX3/4/6/8/8R; T2D2, T2D3, T3D2, T3D3 (line "
                     "elements).", true),
        name("ELSET", "Also add the elements to this element set.")},
       handle_element, ""},
      {"NSET", kModelData | kStep, "Defines or extends a node set (also inside a step, as CalculiX allows).",
       "node labels or names of node sets; with GENERATE: `first, last[, increment]`",
       {name("NSET", "Name of the set.", true), flag("GENERATE", "Data lines are `first, last[, increment]`."),
        name("INSTANCE", "ABAQUS/CAE, in the assembly: the labels and set names are those of this instance."),
        flag("INTERNAL", "ABAQUS/CAE: a set CAE made for its own use; read like any other.")},
       handle_nset, ""},
      {"ELSET", kModelData | kStep, "Defines or extends an element set (also inside a step, as CalculiX allows).",
       "element labels or names of element sets; with GENERATE: `first, last[, increment]`",
       {name("ELSET", "Name of the set.", true),
        flag("GENERATE", "Data lines are `first, last[, increment]`."),
        name("INSTANCE", "ABAQUS/CAE, in the assembly: the labels and set names are those of this instance."),
        flag("INTERNAL", "ABAQUS/CAE: a set CAE made for its own use; read like any other.")},
       handle_elset, ""},
      {"SURFACE", kModelData, "Defines a surface from element faces or from nodes.",
       "TYPE=ELEMENT: `element_or_elset, S1..S4`, or `element_or_elset` alone: the exposed faces of those solid "
       "elements (faces no other element shares, as in ABAQUS), and for line elements (a Gmsh physical curve) the "
       "face of the solid element each lies on; TYPE=NODE: `node_or_nset[, area]` (the area of each node, default 1: a node-based contact slave's pressure is its force / area; calculix dialect: CalculiX's areas, no area field, see Dialects)",
       {name("NAME", "Name of the surface.", true),
        choice("TYPE", "ELEMENT", {"ELEMENT", "NODE"}, "Element-face surface or node surface.")},
       handle_surface, ""},
      // --- model data: materials and sections ---
      {"MATERIAL", kModelData, "Starts a material; the material options (*ELASTIC, ...) follow it.", "",
       {name("NAME", "Name of the material.", true)}, handle_material, ""},
      {"ELASTIC", kMaterial, "Isotropic linear elasticity (small strain; St. Venant-Kirchhoff under NLGEOM).",
       "`E, nu[, temperature]` with E > 0 and -1 < nu < 0.5: one line holds at every temperature; several lines "
       "`E, nu, temperature` (temperatures strictly increasing) are a table interpolated linearly at the point's "
       "temperature, constant beyond its ends (as ABAQUS and CalculiX); a table with *PLASTIC is refused. Dialects: a "
       "deck without temperatures reads a table at temperature 0 (abaqus) or at its first row (calculix), with a "
       "warning where the two differ (first row below 0)",
       {choice("TYPE", "ISOTROPIC", {"ISOTROPIC"}, "Only isotropic elasticity is supported.")}, handle_elastic,
       ""},
      {"HYPERELASTIC", kMaterial, "Compressible neo-Hookean hyperelasticity.", "`C10, D1[, temperature]` with C10 > 0, D1 > 0",
       {flag("NEO HOOKE", "Neo-Hookean strain energy (required; the only model supported).")},
       handle_hyperelastic, ""},
      {"PLASTIC", kMaterial,
       "Von Mises plasticity on the material's *ELASTIC range (small strain; multiplicative with Hencky elasticity "
       "under NLGEOM, every hardening kind and element family; docs/theory/plasticity.md): true yield "
       "stress against equivalent plastic strain, piecewise linear, constant beyond the last row.",
       "`yield stress, plastic strain[, temperature]` per line, yield stress > 0; without temperatures one curve, "
       "plastic strain 0 on the first line and strictly increasing; with them one such curve per temperature, the "
       "temperatures increasing from curve to curve, interpolated linearly in temperature at the same plastic "
       "strain and constant outside their range (as ABAQUS); no field variables",
       {choice("HARDENING", "ISOTROPIC", {"ISOTROPIC", "KINEMATIC", "COMBINED"},
               "ISOTROPIC: the yield stress follows the table; KINEMATIC: the yield stress stays the first one and "
               "the back stress grows with the table's slope (Prager-Ziegler, linear kinematic hardening for two "
               "rows); COMBINED (small strain): the yield stress follows *CYCLIC HARDENING and the back stress "
               "grows with this table's slope, as CalculiX reads it.")},
       handle_plastic, ""},
      {"CYCLIC HARDENING", kMaterial,
       "The isotropic part of *PLASTIC, HARDENING=COMBINED (given after it): the yield stress against the "
       "equivalent plastic strain, piecewise linear, constant beyond the last row.",
       "`yield stress, plastic strain[, temperature]` per line, as for *PLASTIC (no PARAMETERS form)",
       {},
       handle_cyclic_hardening, ""},
      {"USER MATERIAL", kMaterial,
       "The material's mechanical behaviour from an ABAQUS UMAT in a shared library, loaded at run time "
       "(src/tether/materials/user_material.h documents the arguments; a gfortran UMAT works as is). Under NLGEOM "
       "it is integrated as ABAQUS/Standard does (Jaumann rate, Hughes-Winget increments) in the polar-rotated "
       "frame (docs/theory/user_material.md); plane-stress elements are refused there.",
       "CONSTANTS values (PROPS), up to 8 per line",
       {{"CONSTANTS", PT::Integer, "", {}, true, "", "Number of constants (NPROPS)."},
        {"LIBRARY", PT::Text, "", {}, true, "",
         "tether extension: the shared library holding the routine (a path with '/' is relative to the working "
         "directory; a bare name is searched by the dynamic loader)."},
        {"SYMBOL", PT::Text, "", {}, false, "",
         "tether extension: the routine's symbol (default umat_, gfortran's name of SUBROUTINE UMAT)."},
        choice("TYPE", "MECHANICAL", {"MECHANICAL"}, "Only mechanical user materials are supported."),
        flag("UNSYMM", "Accepted and ignored: tether never assumes a user material's tangent symmetric.")},
       handle_user_material, ""},
      {"DEPVAR", kMaterial, "Number of solution-dependent state variables (NSTATV) of a *USER MATERIAL.",
       "`n` with n >= 0", {}, handle_depvar, ""},
      {"DENSITY", kMaterial,
       "Mass density, for the element masses (consistent or lumped; docs/theory/elements.md, section Mass). "
       "Optional: static steps do not use it; asking for the mass of an element whose material has none is an "
       "error naming the material.",
       "one line `rho[, temperature]` with rho > 0 [mass/volume] (a single line holds at every temperature)", {},
       handle_density, ""},
      {"DAMPING", kMaterial,
       "Rayleigh damping of the material in dynamic steps: C = ALPHA M + BETA K (K the element's tangent). "
       "Explicit steps integrate the ALPHA part exactly and apply BETA K to the lagged velocity, which lowers the "
       "stable increment to (2/omega)(sqrt(1 + xi^2) - xi), xi = BETA omega / 2.",
       "",
       {real("ALPHA", "0", "Mass-proportional factor [1/time]."),
        real("BETA", "0", "Stiffness-proportional factor [time]."),
        real("STRUCTURAL", "", "Structural damping of frequency-domain procedures: refused.")},
       handle_damping, ""},
      {"SOLID SECTION", kModelData, "Assigns a material (and thickness) to an element set.",
       "optional `thickness` (default 1; ignored for axisymmetric elements)",
       {name("ELSET", "Element set the section applies to.", true),
        name("MATERIAL", "Name of the material.", true),
        real("OFFSET", "0", "Accepted for CalculiX compatibility: only 0 (a solid section has no offset)."),
        choice("FAMILY", "", {"PLANE STRAIN", "PLANE STRESS", "AXISYMMETRIC"},
               "tether extension: turns the set's elements into this family, keeping their shape and integration "
               "(CPS4 becomes CPE4 or CAX4), e.g. for a Gmsh export, which writes plane-stress CPS elements only.")},
       handle_solid_section, ""},
      {"AMPLITUDE", kModelData | kStep, "Piecewise-linear time function, constant beyond its ends.",
       "pairs `t, a` (any number per line, over as many lines as needed), times strictly increasing",
       {name("NAME", "Name of the amplitude.", true),
        choice("TIME", "STEP TIME", {"STEP TIME", "TOTAL TIME"}, "Time measure of the table."),
        choice("DEFINITION", "TABULAR", {"TABULAR"}, "Only tabular amplitudes are supported.")},
       handle_amplitude, ""},
      // --- boundary conditions and loads (model data for *BOUNDARY, else history data) ---
      {"BOUNDARY", kModelData | kAnyStep, "Prescribes displacement components.",
       "`node_or_nset, first_dof[, last_dof[, value]]` or `node_or_nset, TYPE` with TYPE one of ENCASTRE, "
       "PINNED, XSYMM, YSYMM, XASYMM, YASYMM, ZASYMM (mapped onto dofs 1-2). Dof 3 with value 0 is "
       "ignored with a warning (2D); dofs 4-6 in a range starting at 1-3 are ignored with a warning; "
       "other dofs are errors",
       {amplitude_param(), op_param(),
        choice("TYPE", "DISPLACEMENT", {"DISPLACEMENT", "VELOCITY"},
               "DISPLACEMENT: the values are displacements. VELOCITY (in a step; ABAQUS): the values are "
               "velocities [length/time], applied at once and held (or times the AMPLITUDE), and the dof moves by "
               "their time integral from where the step found it; a later step keeps the velocity until the dof "
               "is given again."),
        flag("FIXED", "In a step: hold the listed dofs at their values at the start of the step (no value on the "
                      "data line); e.g. a bolt's pretension node after its *CLOAD step, to keep the bolt's length.")},
       handle_boundary, ""},
      {"CLOAD", kAnyStep, "Concentrated nodal forces.", "`node_or_nset, dof (1 or 2), magnitude`",
       {amplitude_param(), op_param()}, handle_cload, ""},
      {"DLOAD", kAnyStep,
       "Pressure on element faces (positive pushes into the face), and body loads per unit mass: gravity (GRAV) "
       "and centrifugal (CENTRIF), which need the material's *DENSITY. Body loads act on the reference volume "
       "(exact under NLGEOM too; a centrifugal load then follows the current positions). A later GRAV or CENTRIF "
       "on the same element replaces the earlier one; a GRAV in another direction on an element that already has "
       "one is refused (CalculiX adds the two, ABAQUS replaces).",
       "`element_or_elset, P1..P4, magnitude` (Pn = pressure on face Sn); `element_or_elset, GRAV, g, dx, dy[, dz]` "
       "(g [length/time^2] along the direction (dx, dy), normalized; dz must be 0); `element_or_elset, CENTRIF, "
       "omega^2, px, py, pz, ax, ay, az` (omega^2 [1/time^2] >= 0, a point on the rotation axis and its "
       "direction: the z axis for plane elements, the symmetry axis `0, y, 0` / `0, 1, 0` for axisymmetric ones)",
       {amplitude_param(), op_param()}, handle_dload, ""},
      {"DSLOAD", kAnyStep, "Pressure on an element-face surface (positive pushes into the face).",
       "`surface, P, magnitude`", {amplitude_param(), op_param()}, handle_dsload, ""},
      // --- steps ---
      {"STEP", kModelData | kBetweenSteps, "Starts a step; ends with *END STEP.", "",
       {choice("NLGEOM", "NO", {"YES", "NO"}, "Geometric nonlinearity (bare NLGEOM means YES). Omitted: as in the previous step (NO in the first); once on, it stays on in every later step, as in ABAQUS (NLGEOM=NO after it is ignored with a warning).", "YES"),
        integer("INC", "100", "Maximum number of increments."), name("NAME", "Name of the step."),
        choice("EXTRAPOLATION", "LINEAR", {"LINEAR", "NO", "PARABOLIC"},
               "Start of each static increment: LINEAR (default, as ABAQUS/Standard) extrapolates the step's last "
               "converged increment to the new increment's size; NO starts from the converged state. PARABOLIC "
               "(ABAQUS's quadratic extrapolation) is refused."),
        choice("AMPLITUDE", "RAMP", {"RAMP", "STEP"},
               "Loads and prescribed values without an amplitude: RAMP from their previous values over the step "
               "(default of *STATIC) or STEP, applied at the step's start and held (default of *DYNAMIC).")},
       handle_step, ""},
      {"STATIC", kAnyStep, "Static procedure with automatic (or fixed, DIRECT) incrementation.",
       "`initial, period, min, max` (defaults 1, 1, 1e-5*period, period)",
       {flag("DIRECT", "Fixed increments of the initial size, no cut-back."),
        name("SOLVER", "Accepted for CalculiX compatibility and ignored (tether chooses the linear solver).")},
       handle_static, ""},
      {"DYNAMIC", kAnyStep,
       "Dynamic procedure: implicit HHT-alpha with Newton (default), or EXPLICIT central differences with lumped "
       "mass and predictor-corrector contact. Needs *DENSITY on every material. Loads without an amplitude are "
       "applied at the step's start and held unless *STEP has AMPLITUDE=RAMP. docs/theory/dynamics.md.",
       "`initial, period, min, max` (implicit; defaults 1, 1, 1e-5*period, period); EXPLICIT: `increment, "
       "period` (the increment is used with DIRECT, else the stable increment is computed)",
       {real("ALPHA", "-0.05", "HHT's alpha, -1/3 <= alpha <= 0 (0: trapezoidal Newmark, no numerical damping)."),
        flag("DIRECT", "Fixed increments of the initial size (implicit: no cut-back)."),
        flag("EXPLICIT", "Central-difference (explicit) integration."),
        real("HAFTOL", "", "ABAQUS's half-increment residual tolerance [force] > 0 (implicit, without DIRECT): "
                           "the increment is repeated smaller when the residual of the equation of motion at its "
                           "middle exceeds HAFTOL, and grows when it stays below HAFTOL/2 "
                           "(docs/theory/dynamics.md). Without it the increment never grows past the initial one."),
        choice("CONTACT MASS", "REDISTRIBUTED", {"REDISTRIBUTED", "KEPT"},
               "tether extension (implicit): contact-surface nodes carry no mass, their mass moved to the other "
               "nodes of their elements, so that impacts with exact multipliers neither chatter nor gain energy "
               "(REDISTRIBUTED), or every node keeps its mass (KEPT)."),
        choice("MASS", "CONSISTENT", {"CONSISTENT", "LUMPED"},
               "tether extension: mass matrix of the implicit procedure (EXPLICIT always lumps)."),
        name("SOLVER", "Accepted for CalculiX compatibility and ignored (tether chooses the linear solver).")},
       handle_dynamic, ""},
      {"CONTROLS", kAnyStep,
       "Convergence and incrementation controls; they stay in force for later steps until RESET.",
       "FIELD: `R_n, C_n, q0, qu, R_P, eps, C_eps, R_l` (R_n, C_n and eps are used); TIME INCREMENTATION: "
       "line 1 `I0, IR, IP, IC, IL, IG, IS, IA, IJ, IT` (IC = max iterations per attempt, IG = easy "
       "iterations, IA = max cut-backs are used), line 2 `Df, DC, DB, DA, DS, DH, DD, WG` (Df = cut-back "
       "factor, DD = growth factor are used); LINE SEARCH: `N_ls` (0 turns it off). Other values are "
       "ignored with a warning",
       {choice("PARAMETERS", "", {"FIELD", "TIME INCREMENTATION", "LINE SEARCH"}, "Which controls the data set."),
        flag("RESET", "Restore all controls to their defaults."),
        choice("FIELD", "GLOBAL", {"GLOBAL", "DISPLACEMENT"}, "Field the FIELD controls apply to (tether has "
                                                               "only displacements).")},
       handle_controls, ""},
      {"END STEP", kAnyStep, "Ends the current step.", "", {}, handle_end_step, ""},
      {"RESTART", kModelData | kAnyStep,
       "Writes the state needed to continue the analysis later (WRITE: JOB.rst in the output directory, replaced "
       "atomically; in force for later steps until changed), or continues from such a state (READ, model data "
       "only; or `tether run DECK --restart FILE.rst`). The deck must describe the same mesh, constraints and "
       "contact and the same loads up to the saved step; see docs/robustness.md.",
       "",
       {flag("WRITE", "Write the restart state (only the last one is kept: OVERLAY)."),
        flag("READ", "Continue from the state in FILE= (or the file given with --restart)."),
        integer("FREQUENCY", "1", "WRITE: after every n-th converged increment of a step (0: stop writing); the "
                                  "end of every step is always written."),
        flag("OVERLAY", "WRITE: keep only the last state (the only mode; accepted for ABAQUS compatibility)."),
        integer("STEP", "", "READ: the state must be from this step (the file holds only the last state "
                            "written; another one is refused)."),
        integer("INC", "", "READ: ... and from this increment of that step (needs STEP)."),
        {"FILE", PT::Text, "", {}, false, "",
         "READ: the restart file, relative to the deck's directory (tether extension; without it the command "
         "line must give --restart)."}},
       handle_restart, ""},
      // --- output requests (apply to their step only) ---
      {"NODE PRINT", kAnyStep, "Nodal values in the text report.", "variables: U, RF; V, A (dynamic steps)",
       {name("NSET", "Node set (default: all nodes)."), frequency_param(),
        choice("TOTALS", "NO", {"YES", "ONLY", "NO"}, "Also (YES) or only (ONLY) print the sums over the set.")},
       handle_node_print, ""},
      {"EL PRINT", kAnyStep, "Element integration-point values in the text report.",
       "variables: S, E, THE (thermal strain), PEEQ (equivalent plastic strain), PE (plastic strain), AC YIELD "
       "(1 where the point flowed plastically in the increment, else 0; also ACYIELD; 0 for a user material), SDV "
       "(a user material's state variables STATEV, CalculiX's block: all NSTATV values of a point on one line, zeros "
       "where a material has fewer; ABAQUS's meaning: tether's own materials have none)",
       {name("ELSET", "Element set (default: all elements)."), frequency_param()}, handle_el_print, ""},
      {"NODE FILE", kAnyStep, "Nodal values in the result files (VTU; V and A are written in dynamic steps).", "variables: U, RF, V, A",
       {name("NSET", "Node set (default: all nodes)."), frequency_param(),
        name("OUTPUT", "Accepted for CalculiX compatibility (2D/3D) and ignored.")},
       handle_node_file, ""},
      {"EL FILE", kAnyStep, "Element values in the result files (VTU; PEEQ, PE, AC_YIELD and ALLPD are written "
       "whenever a material is plastic, THE whenever the deck gives temperatures, SDV1, SDV2, ... (per cell the "
       "mean over its points, per node extrapolated and averaged as S) whenever a user material has *DEPVAR).",
       "variables: S, E, THE, PEEQ, PE, AC YIELD, SDV",
       {name("ELSET", "Element set (default: all elements)."), frequency_param(),
        name("OUTPUT", "Accepted for CalculiX compatibility (2D/3D) and ignored.")},
       handle_el_file, ""},
      {"OUTPUT", kAnyStep, "Starts an ABAQUS output block: FIELD (result files) or HISTORY (text report).", "",
       {flag("FIELD", "Field output: *NODE OUTPUT / *ELEMENT OUTPUT go to the result files."),
        flag("HISTORY", "History output: they go to the text report."), frequency_param(),
        integer("NUMBER INTERVAL", "", "Write at the ends of n equal intervals of the step (instead of "
                                       "FREQUENCY). Static and implicit steps: the first increment ending at or "
                                       "after each mark; explicit steps: the marks rounded to the step's nominal "
                                       "explicit increment, where a report ends."),
        real("TIME INTERVAL", "", "Write at every multiple of this step time (instead of FREQUENCY), as "
                                  "NUMBER INTERVAL does its marks; the end of the step is always written."),
        choice("TIME MARKS", "NO", {"YES", "NO"},
               "YES: static and implicit increments are shortened to end on the marks of NUMBER or TIME "
               "INTERVAL; NO (ABAQUS's default): the first increment ending at or after a mark writes. "
               "Explicit reports end on the marks either way."),
        choice("VARIABLE", "", {"PRESELECT", "ALL"},
               "ABAQUS's default variables for the whole model: FIELD requests U, RF, S and E (and CSTR, CDIS "
               "when the model has contact pairs) in the result files; HISTORY means the whole-model energies, "
               "which tether writes to the .dat of dynamic steps anyway (static steps have none yet), so it "
               "requests nothing more.")},
       handle_output, ""},
      {"NODE OUTPUT", kAnyStep, "Nodal variables of the current *OUTPUT block.", "variables: U, RF",
       {name("NSET", "Node set (default: all nodes).")}, handle_node_output, ""},
      {"ELEMENT OUTPUT", kAnyStep, "Element variables of the current *OUTPUT block.",
       "variables: S, E, THE, PEEQ, PE, AC YIELD, SDV",
       {name("ELSET", "Element set (default: all elements).")}, handle_element_output, ""},
      // --- model data: constraints ---
      {"EQUATION", kModelData, "Linear constraint sum_i c_i u_i = 0 between dofs (ABAQUS syntax).",
       "the number of terms n, then n terms `node_or_nset, dof, coefficient`, up to four per line; repeat for "
       "more equations. Node sets apply the equation member by member.",
       enforcement_params({}), handle_equation, ""},
      {"MPC", kModelData,
       "Multi-point constraints: TIE/PIN (equal displacements), LINK (constant distance), SLIDER (node on the line "
       "through two others), BEAM (node a moves rigidly with node b, which gets an in-plane rotation, dof 6); with "
       "USER, an ABAQUS-style MPC routine in a shared library.",
       "`TYPE, node_a, node_b[, node_c]`, one constraint per line; with USER: `JTYPE, node1, node2, ...` (a "
       "trailing ',' continues the node list)",
       enforcement_params({flag("USER", "The constraint is computed by a user routine (see examples/user_mpc)."),
                           choice("MODE", "DOF", {"DOF", "NODE"},
                                  "USER: DOF eliminates one dof at a time; NODE several dofs of the first node."),
                           {"LIBRARY", PT::Text, "", {}, false, "", "USER: shared library (relative to the deck)."},
                           {"SYMBOL", PT::Text, "tether_user_mpc", {}, false, "",
                            "USER: name of the routine in the library."}}),
       handle_mpc, ""},
      {"CONSTRAINT", kModelData,
       "tether extension: a general constraint f(u) = 0 written as formulas (TYPE=EXPRESSION) or computed by a "
       "user routine in a shared library (TYPE=USER).",
       "first line: the node labels (a trailing ',' continues the list); then EXPRESSION: one formula per line "
       "in Xk, Yk (reference coordinates of node k), Uk, Vk (its displacements) and T (time); USER: the "
       "property list",
       enforcement_params({{"TYPE", PT::Choice, "", {"USER", "EXPRESSION"}, true, "", "Formula or user routine."},
                           {"LIBRARY", PT::Text, "", {}, false, "", "TYPE=USER: shared library (relative to the deck)."},
                           {"SYMBOL", PT::Text, "tether_user_constraint", {}, false, "",
                            "TYPE=USER: name of the routine in the library."},
                           integer("MULTIPLIERS", "1", "TYPE=USER: number of multipliers the routine uses."),
                           integer("NODES", "0", "Number of nodes (optional; checked against the node list)."),
                           integer("FLAG", "0", "TYPE=USER: integer passed to the routine as `flag`.")}),
       handle_constraint, ""},
      {"TIE", kModelData,
       "Ties the nodes of a slave surface to a master surface (non-matching meshes): each slave node within "
       "POSITION TOLERANCE of the master surface gets two linear equations (x and y) tying it to the master "
       "face(s), with weights fixed in the reference configuration (small sliding; see TYPE). Slave nodes "
       "farther away are not tied (a warning lists them); slave nodes that are also master nodes are skipped; "
       "a line that ties no node is an error.",
       "`slave_surface, master_surface` (slave: element faces or TYPE=NODE; master: element faces, 2- or 3-node); "
       "one pair per line",
       enforcement_params(
           {real("POSITION TOLERANCE", "0",
                 "Largest distance of a tied slave node from the master surface (0: 5 % of the mean master face "
                 "length, as ABAQUS)."),
            choice("ADJUST", "YES", {"YES", "NO"},
                   "YES: move tied slave nodes onto the master surface in the reference configuration (a warning "
                   "says how many and how far) before the analysis."),
            choice("TYPE", "SURFACE TO SURFACE", {"NODE TO SURFACE", "SURFACE TO SURFACE"},
                   "SURFACE TO SURFACE (ABAQUS's default): mortar equations sum_l D_kl u_l - sum_i M_ki u_i = 0 "
                   "per slave node, integrated over the slave faces; passes the patch test on any non-matching "
                   "straight interface. NODE TO SURFACE: u_s = sum_i N_i(xi*) u_i, exact only where the master "
                   "nodes sit at slave node positions. A node slave surface is always NODE TO SURFACE.")}),
       handle_tie, ""},
      {"PERIODIC", kModelData,
       "tether extension: periodic boundary conditions of a cell (RVE). Node a of the first set and its partner b "
       "of the second (at X_a + translation) get u_b - u_a = H (X_b - X_a), one equation per component, where the "
       "macroscopic displacement gradient H = [[u_R1x, u_R2x], [u_R1y, u_R2y]] has as columns the displacements "
       "of the reference nodes REFERENCE1 and REFERENCE2. Prescribe or load the reference nodes to load the cell: "
       "their reactions are the macroscopic stress times the cell volume, F(R1) = V (S11, S21), F(R2) = V (S12, "
       "S22) (V = area times thickness). A pair already implied by earlier pairs (the corners of a cell paired "
       "along x and y) is not written again, so the equations stay independent.",
       "`nset_a, nset_b[, dx, dy]`: opposite node sets, paired by the translation (dx, dy) (default: from the "
       "centroid of a to the centroid of b); one pair of sets per line",
       enforcement_params({name("REFERENCE1", "Node (label or one-node set) whose displacement is the first column "
                                              "of H: (H11, H21).", true),
                           name("REFERENCE2", "Node whose displacement is the second column of H: (H12, H22).", true),
                           real("POSITION TOLERANCE", "0",
                                "Largest distance between X_a + translation and the partner of a (0: 1e-6 times "
                                "the translation length).")}),
       handle_periodic, ""},
      {"PRE-TENSION SECTION", kModelData,
       "Bolt pretension: the surface cuts a continuum bolt in two; tether duplicates the surface's nodes (the "
       "surface's elements take the copies) and joins each pair again by (u_b - u_a).t = 0 and (u_b - u_a).n = "
       "u_p, where u_p, dof 1 of the pretension node, is the tightening (positive shortens the bolt). *CLOAD on "
       "that dof sets the bolt force (positive: tension); *BOUNDARY on it prescribes the tightening, and "
       "*BOUNDARY, FIXED in a later step holds the bolt's length. The .dat lists each section's tightening and "
       "bolt force at every written increment. The equations are enforced by multipliers.",
       "optional: the section's normal `nx, ny[, nz]` (nz = 0), pointing from the surface's elements across the "
       "cut; default: the length-weighted mean outward normal of the surface's faces",
       {name("SURFACE", "Element-face surface: the faces of the bolt elements on one side of the cut."),
        name("NODE", "Pretension node (label or one-node set): a node no element uses; only its dof 1 is active.",
             true),
        name("ELEMENT", "Truss or beam bolt element (ABAQUS); refused: tether has 2D continuum elements only.")},
       handle_pre_tension_section, ""},
      // --- model data: contact ---
      {"SURFACE INTERACTION", kModelData, "Starts a contact property; *SURFACE BEHAVIOR and *FRICTION follow it.", "",
       {name("NAME", "Name of the interaction.", true)}, handle_surface_interaction, ""},
      {"SURFACE BEHAVIOR", kInteraction, "Pressure-overclosure law of the interaction (default HARD).",
       "HARD: none; LINEAR: `K` (abaqus dialect: p = K h), `K, sigma_inf, c0` (calculix dialect: CalculiX's law, "
       "see Dialects); "
       "EXPONENTIAL: `c0, p0` (ABAQUS's or CalculiX's function, by dialect); TABULAR: pairs `pressure, "
       "overclosure` with overclosure increasing",
       {{"PRESSURE-OVERCLOSURE", PT::Choice, "HARD", {"HARD", "LINEAR", "EXPONENTIAL", "TABULAR"}, false, "",
         "HARD contact is enforced exactly (by multipliers, not CalculiX's K = 50 E penalty) in both dialects; the "
         "calculix dialect says so in a warning."},
        choice("ENFORCEMENT", "LAGRANGE", {"LAGRANGE", "PENALTY", "AUGMENTED"},
               "tether extension, HARD only: LAGRANGE multipliers (exact; regularised with EPSILON), PENALTY "
               "(N = PENALTY x overclosure) or AUGMENTED Lagrangian (penalty plus Uzawa updates until the largest "
               "penetration is below TOLERANCE)."),
        real("EPSILON", "0", "HARD, LAGRANGE: regularise to gap + EPSILON x normal force >= 0 [length/force]."),
        real("PENALTY", "", "HARD, PENALTY or AUGMENTED: penalty stiffness [force/length]."),
        real("TOLERANCE", "0", "HARD, AUGMENTED: penetration [length] that ends the Uzawa updates (0: 1e-8 times "
                               "the longest contact face).")},
       handle_surface_behavior, ""},
      {"FRICTION", kInteraction, "Coulomb friction of the interaction.",
       "`mu[, stick slope]` (the stick slope is CalculiX's; 0 or absent: exact stick)",
       {real("ELASTIC SLIP", "0", "ABAQUS: slip at which the full friction force is reached (a stick penalty).")},
       handle_friction, ""},
      {"CONTACT PAIR", kModelData, "Contact of a slave surface against a master surface (node to surface, or mortar).",
       "`slave_surface, master_surface` (master: element faces; slave: element faces or nodes, mortar: element "
       "faces only; the stiffer "
       "body should be the master: a slave 10 or more times stiffer is warned about)",
       {name("INTERACTION", "The *SURFACE INTERACTION to use.", true),
        choice("TYPE", "NODE TO SURFACE",
               {"NODE TO SURFACE", "SURFACE TO SURFACE", "MORTAR", "LINMORTAR", "PGMORTAR", "PGLINMORTAR"},
               "NODE TO SURFACE; SURFACE TO SURFACE or MORTAR (CalculiX): mortar contact with dual multipliers "
               "(slave: element faces; HARD by multipliers or a soft PRESSURE-OVERCLOSURE law of the mean "
               "overclosure -g~_j / D_j, frictionless or Coulomb friction with exact stick). "
               "CalculiX's LINMORTAR, PGMORTAR and PGLINMORTAR are refused."),
        flag("SMALL SLIDING", "Keep the pairing found at the start (no re-pairing while sliding). Mortar: "
                              "warned about, the segmentation is updated at every iteration all the same."),
        real("ADJUST", "0", "Move slave nodes within this clearance onto the master surface before the analysis."),
        real("SMOOTH", "0", "Round each corner of a linear master surface over this fraction s of both adjacent faces "
                            "(0 < s <= 0.5; a C1 surface, continuous normal). Absent or 0: no smoothing (ABAQUS "
                            "smooths by 0.2 by default; tether only when asked). Quadratic master faces are refused, and so is "
                            "SMOOTH with mortar contact.")},
       handle_contact_pair, ""},
      {"INITIAL CONDITIONS", kModelData, "Initial values: TYPE=VELOCITY (the velocity at the start of the first "
       "dynamic step) or TYPE=TEMPERATURE (the initial nodal temperatures: the thermal strain is zero at them; "
       "nodes not given start at 0). Other types are refused.",
       "VELOCITY: `node or node set, dof, velocity` (dof 1 or 2) [length/time]; TEMPERATURE: `node or node set, "
       "temperature`",
       {name("TYPE", "VELOCITY or TEMPERATURE (other types are refused).", true)}, handle_initial_conditions, ""},
      {"EXPANSION", kMaterial,
       "Isotropic thermal expansion: the secant coefficient alpha(T) about ZERO, thermal strain "
       "alpha(T)(T - ZERO) - alpha(T_I)(T_I - ZERO) with T_I the initial temperature (ABAQUS's and CalculiX's "
       "meaning). Small strain: subtracted from the strain; NLGEOM: F = (1 + eps_th) F_m.",
       "`alpha[, temperature]`; several lines `alpha, temperature` (temperatures strictly increasing) are a table "
       "interpolated linearly, constant beyond its ends",
       {real("ZERO", "0", "Reference temperature of the coefficient [temperature]."),
        choice("TYPE", "ISO", {"ISO"}, "Only isotropic expansion is supported.")},
       handle_expansion, ""},
      {"TEMPERATURE", kAnyStep,
       "Nodal temperatures of the step. Nodes not listed keep their temperature (their initial one before any "
       "step); without AMPLITUDE= a value is ramped from the node's temperature at the step's start (static "
       "steps) or applied at once (AMPLITUDE=STEP, dynamic steps). The point temperature is the shape-function "
       "interpolation of the nodal values (a user material reads it as TEMP and DTEMP). Warned about when no material has *EXPANSION, a temperature table or *USER MATERIAL.",
       "`node or node set, temperature`",
       {name("AMPLITUDE", "Amplitude: the temperature is value * a(t)."),
        choice("OP", "MOD", {"MOD", "NEW"},
               "MOD: replace the values of the nodes listed; NEW: nodes not listed return to their initial "
               "temperature (ramped like a removed load)."),
        name("FILE", "ABAQUS: temperatures from a results file (refused).")},
       handle_temperature, ""},
      {"CONTACT PRINT", kAnyStep, "Contact output in the .dat report.", "variables: CSTR, CDIS (CalculiX), CSTRESS, CDISP, CFN, CFS (ABAQUS)",
       {frequency_param(),
        name("SET", "Not a parameter of either program: ccx 2.20 warns and ignores it, so does the calculix dialect; "
                    "refused in the abaqus dialect.")},
       handle_contact_output, ""},
      {"CONTACT FILE", kAnyStep, "Contact output in the result files.", "variables: CSTR, CDIS",
       {frequency_param()}, handle_contact_output, ""},
      {"CONTACT OUTPUT", kAnyStep, "Contact output request (ABAQUS).", "variables: CSTRESS, CDISP, CFN, CFS",
       {frequency_param()}, handle_contact_output, ""},
      // --- recognised, not supported yet: a clear error, never silently dropped ---
      {"ORIENTATION", kModelData, "Local material directions.", "", {}, nullptr,
       "tether's materials are isotropic"},
      {"TRANSFORM", kModelData, "Local nodal directions.", "", {}, nullptr, kLater},
      {"FREQUENCY", kAnyStep, "Eigenfrequency procedure.", "", {}, nullptr,
       "tether has static and dynamic (*DYNAMIC) procedures, no eigenvalue extraction"},
      {"BUCKLE", kAnyStep, "Buckling procedure.", "", {}, nullptr,
       "tether has static and dynamic (*DYNAMIC) procedures, no eigenvalue extraction"},
      {"HEAT TRANSFER", kAnyStep, "Heat-transfer procedure.", "", {}, nullptr, "tether has no thermal analysis"},
  };
}

}  // namespace

const std::vector<KeywordSpec>& keyword_table() {
  static const std::vector<KeywordSpec> table = build_table();
  return table;
}

const KeywordSpec* lookup_keyword(std::string_view name) {
  for (const KeywordSpec& k : keyword_table())
    if (k.name == name) return &k;
  return nullptr;
}

const KeywordSpec& find_keyword(std::string_view name) {
  const KeywordSpec* k = lookup_keyword(name);
  if (!k) throw std::out_of_range("keyword table has no *" + std::string(name));
  return *k;
}

std::string context_text(unsigned where) {
  std::string out;
  const auto add = [&](unsigned bit, const char* text) {
    if (!(where & bit)) return;
    if (!out.empty()) out += ", ";
    out += text;
  };
  add(kModelData, "model data (before the first *STEP)");
  add(kMaterial, "material data (after *MATERIAL)");
  add(kInteraction, "surface interaction data (after *SURFACE INTERACTION)");
  add(kStep, "inside a step (*STEP ... *END STEP)");
  add(kBetweenSteps, "between steps");
  return out;
}

}  // namespace tether::deck
