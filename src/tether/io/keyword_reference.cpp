// keyword_reference_markdown(): docs/keywords.md rendered from the keyword table.
#include <sstream>

#include "tether/io/deck_reader.hpp"
#include "tether/io/keyword_table.hpp"

namespace tether {

namespace {

std::string type_text(const deck::ParameterSpec& p) {
  using PT = deck::ParameterType;
  switch (p.type) {
    case PT::Flag: return "flag";
    case PT::Name: return "name";
    case PT::Text: return "text";
    case PT::Integer: return "integer";
    case PT::Real: return "real";
    case PT::Choice: {
      std::string out;
      for (std::string_view c : p.choices) out += (out.empty() ? "" : " \\| ") + std::string(c);
      if (!p.flag_value.empty()) out += " (bare: " + std::string(p.flag_value) + ")";
      return out;
    }
  }
  return "";
}

/// Where ABAQUS and CalculiX read the same data differently, and what tether does.
std::string dialects_section() {
  return "## Dialects\n\n"
         "`tether run|check --dialect abaqus|calculix` (default abaqus) chooses the meaning where ABAQUS and "
         "CalculiX give the same data different meanings; the `.msg` and `.sta` name the dialect. tether never "
         "picks the other meaning silently: a case whose meaning in the chosen dialect tether does not model is "
         "refused with a file:line error.\n\n"
         "| data | abaqus | calculix |\n| --- | --- | --- |\n"
         "| *SURFACE BEHAVIOR, PRESSURE-OVERCLOSURE=EXPONENTIAL `c0, p0` | p = p0/(e-1) (h/c0+1)(exp(h/c0+1)-1) "
         "for h > -c0, else 0 | p = p0 exp(ln(100) h/c0) at every clearance (1 % of p0 at h = -c0) |\n"
         "| PRESSURE-OVERCLOSURE=LINEAR | `K` only: p = K h; a second or third field (CalculiX's sigma_inf, c0) "
         "is refused, pointing to the calculix dialect | `K, sigma_inf, c0` (each optional, by position): "
         "node-to-surface p = K h (1/2 + atan(h/eps)/pi), eps = pi sigma_inf/K, smooth, with a tension up to "
         "sigma_inf at open gaps while the clearance is within c0 sqrt(A/2) (A: tether's node area; CalculiX's "
         "expanded 3D node has half of it), none beyond; defaults K = 50 E, sigma_inf = E/70000 (E of the first "
         "material), c0 = 1e-3. Refused on SURFACE TO SURFACE pairs (CalculiX's face-to-face law p = -K g is "
         "not modelled). CalculiX takes the node areas on the deformed slave face, tether on the undeformed one "
         "(0.19 % apart in u on two CPE4 blocks with nu = 0.3, 6e-5 with nu = 0) |\n"
         "| PRESSURE-OVERCLOSURE=HARD | exact (multipliers) | exact (multipliers), with a warning: CalculiX "
         "itself uses its LINEAR penalty with K = 50 E, sigma_inf = E/70000 |\n"
         "| *SURFACE, TYPE=NODE as a contact slave | each node's area is 1 or as its data line gives | CalculiX's: "
         "the area of the master face the node projects onto, at that point (ccx keeps the 2D node, which lies "
         "on no face of its expanded 3D mesh, gives it the area 0 and then uses the master face's "
         "4 |x_xi x x_eta|): 2 t |y'(xi)| on faces of plane elements (face length x thickness when straight); on "
         "faces of CAX elements 180 x that of ccx's 2-degree segment, 720 sin(1 deg) r |(r', y')| with r' scaled "
         "by cos(1 deg) on linear faces (about 2 pi r x face length); on the current (deformed) master face at "
         "the current projection, with or without NLGEOM, as ccx; pressure = force / that area; CalculiX's LINEAR law "
         "acts at such a node only within a clearance of 1e-10 (ccx's reach for area 0). Refused: an area on the "
         "data line, a node in no element, plane slave nodes against axisymmetric master faces or the reverse "
         "(ccx's spring acts on a 2-degree segment on one side and the whole thickness on the other; element-face "
         "surfaces that mix the two are refused too) |\n"
         "| *NODE PRINT RF of nodes of axisymmetric elements | totals over the full circle | CalculiX's 2-degree "
         "segment: the full-circle values / 180 (concentrated loads are full-circle values in both, as in ccx) "
         "|\n"
         "| FREQUENCY on *NODE PRINT, *EL PRINT, *CONTACT PRINT | per request | one value for all print requests "
         "of the step: the last FREQUENCY given on any of them, carried to later steps (1 until one is given) |\n"
         "| output requests of a *DYNAMIC, EXPLICIT step without FREQUENCY, NUMBER INTERVAL or TIME INTERVAL "
         "| as ABAQUS/Explicit's default output: 20 equal intervals of the step for the result files (field "
         "output), 200 for the .dat (history output) | every explicit increment (CalculiX's FREQUENCY=1; ccx "
         "2.20 measured), with a warning; in both dialects FREQUENCY=n counts explicit increments |\n"
         "| *STEP, NLGEOM=NO after a step with NLGEOM | stays on, with a warning | turned off |\n"
         "| *BOUNDARY displacements without AMPLITUDE in a *DYNAMIC (implicit) step, or in any step with *STEP, "
         "AMPLITUDE=STEP | ramped over the step from the previous value (ABAQUS/Standard always ramps "
         "TYPE=DISPLACEMENT) | applied at the step's start and held (ccx 2.20 prints the full value at every "
         "increment); *DYNAMIC, EXPLICIT holds them in both dialects |\n\n"
         "The same in both dialects: names may be used before their definition (CalculiX's reading order, see "
         "above); a second GRAV in another direction on an element is refused (CalculiX adds the two, ABAQUS "
         "replaces the first); print requests carry into later steps that do not repeat them (both programs do); "
         "*BOUNDARY, TYPE=VELOCITY is ABAQUS's prescribed velocity (ccx 2.20 does not know the parameter: it "
         "warns and applies the value as a displacement).\n\n"
         "Known differences the dialect does not switch: CalculiX's node-to-surface contact gives the "
         "nodes of quadratic slave faces areas with its own weights (1/100 at corners, 24/100 at mid-sides of an "
         "8-node face, in its source), tether the consistent ones.\n\n";
}

}  // namespace

std::string keyword_reference_markdown() {
  std::ostringstream md;
  md << "# Deck keywords\n\n"
     << "Generated by `tether::keyword_reference_markdown()` from the reader's declaration table "
        "(src/tether/io/keyword_table.cpp); do not edit by hand.\n\n"
     << "Keywords, parameters and choices are case-insensitive; `**` starts a comment; a keyword line "
        "ending with `,` continues on the next line; data lines are comma-separated and may end with `,`; a "
        "lone `*` line is skipped with a warning (as CalculiX does).\n\n"
     << "Model data may name things defined further down, as CalculiX allows: the reader takes the keywords in "
        "CalculiX's order, by group and in deck order within each group: *NODE, *ELEMENT, *NSET, *ELSET, "
        "*SURFACE, *MATERIAL with its options, *TIE, *SURFACE INTERACTION with its options, *INITIAL "
        "CONDITIONS, *AMPLITUDE, *CONTACT PAIR, then everything else (sections, constraints, loads, steps). So "
        "a *CONTACT PAIR may come before the *SURFACE INTERACTION it names, a *SOLID SECTION before its "
        "*MATERIAL and *ELSET, an *ELEMENT before its *NODE lines; a set that names another set still comes "
        "after it. Errors name the line that refers to the missing name. Model data still ends at the first "
        "*STEP, and an *NSET, *ELSET or *AMPLITUDE written inside a step is read with the model data, before "
        "every step (as in CalculiX).\n\n"
     << "Output requests (*NODE PRINT, *EL PRINT, *CONTACT PRINT, *NODE FILE, *EL FILE, *CONTACT FILE and "
        "*OUTPUT's *NODE OUTPUT / *ELEMENT OUTPUT) stay in force in later steps, as in ABAQUS and CalculiX: a "
        "step that gives none of a kind keeps the previous step's requests of that kind; the first request of a "
        "kind in a step replaces them all (FREQUENCY=0 turns that kind off). V and A are dropped, with a "
        "warning, from requests carried into a *STATIC step.\n\n";
  md << "## Supported keywords\n\n";
  for (const deck::KeywordSpec& k : deck::keyword_table()) {
    if (!k.not_supported.empty()) continue;
    md << "### *" << k.name << "\n\n" << k.description << "\n\n";
    md << "- Where: " << deck::context_text(k.where) << "\n";
    if (!k.data.empty()) md << "- Data lines: " << k.data << "\n";
    md << "\n";
    if (k.parameters.empty()) {
      md << "No parameters.\n\n";
      continue;
    }
    md << "| parameter | value | default | description |\n| --- | --- | --- | --- |\n";
    for (const deck::ParameterSpec& p : k.parameters)
      md << "| " << p.name << " | " << type_text(p) << " | "
         << (p.required ? "required" : (p.default_value.empty() ? "-" : std::string(p.default_value))) << " | "
         << p.description << " |\n";
    md << "\n";
  }
  md << dialects_section();
  md << "## Recognised but not supported yet\n\n"
     << "These keywords stop the reader with a file:line error instead of being silently dropped.\n\n"
     << "| keyword | what it is | status |\n| --- | --- | --- |\n";
  for (const deck::KeywordSpec& k : deck::keyword_table())
    if (!k.not_supported.empty()) md << "| *" << k.name << " | " << k.description << " | " << k.not_supported << " |\n";
  return md.str();
}

}  // namespace tether
