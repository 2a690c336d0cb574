#pragma once
/// \file One handler per supported keyword (see keyword_table.cpp for the
/// declarations of their parameters). Each reads one keyword block into the
/// DeckState and throws InputError (file:line) on bad input.

#include "tether/io/keyword_table.hpp"
#include "tether/model/model.hpp"

namespace tether::deck {

#define TETHER_DECK_HANDLER(name) void name(DeckState&, const KeywordBlock&, const ParameterValues&)

// mesh_keywords.cpp
TETHER_DECK_HANDLER(handle_heading);
TETHER_DECK_HANDLER(handle_preprint);
TETHER_DECK_HANDLER(handle_node);
TETHER_DECK_HANDLER(handle_element);
// set_keywords.cpp
TETHER_DECK_HANDLER(handle_nset);
TETHER_DECK_HANDLER(handle_elset);
TETHER_DECK_HANDLER(handle_surface);
// material_keywords.cpp
TETHER_DECK_HANDLER(handle_material);
TETHER_DECK_HANDLER(handle_elastic);
TETHER_DECK_HANDLER(handle_hyperelastic);
TETHER_DECK_HANDLER(handle_density);
// plastic_keywords.cpp
TETHER_DECK_HANDLER(handle_plastic);
TETHER_DECK_HANDLER(handle_cyclic_hardening);
// user_material_keywords.cpp
TETHER_DECK_HANDLER(handle_user_material);
TETHER_DECK_HANDLER(handle_depvar);
TETHER_DECK_HANDLER(handle_solid_section);
// load_keywords.cpp
TETHER_DECK_HANDLER(handle_amplitude);
TETHER_DECK_HANDLER(handle_boundary);
TETHER_DECK_HANDLER(handle_cload);
TETHER_DECK_HANDLER(handle_dload);
TETHER_DECK_HANDLER(handle_dsload);
// step_keywords.cpp
TETHER_DECK_HANDLER(handle_step);
TETHER_DECK_HANDLER(handle_static);
TETHER_DECK_HANDLER(handle_dynamic);
TETHER_DECK_HANDLER(handle_controls);
TETHER_DECK_HANDLER(handle_end_step);
TETHER_DECK_HANDLER(handle_restart);
// dynamic_keywords.cpp
TETHER_DECK_HANDLER(handle_initial_conditions);
TETHER_DECK_HANDLER(handle_damping);
// thermal_keywords.cpp
TETHER_DECK_HANDLER(handle_expansion);
TETHER_DECK_HANDLER(handle_temperature);
/// `*INITIAL CONDITIONS, TYPE=TEMPERATURE` (called by handle_initial_conditions).
void handle_initial_temperatures(DeckState& state, const KeywordBlock& block);
/// `*ELASTIC` with several rows `E, nu, temperature`: fills the temperature
/// table of `elastic` (and its first-row E, nu); InputError (file:line) for a
/// bad row or temperatures that do not increase.
void read_elastic_table(const KeywordBlock& block, MaterialData::Elastic& elastic);
/// After the whole deck: a deck without temperatures reads a temperature-
/// dependent *ELASTIC at temperature 0 (ABAQUS) or at its first row
/// (CalculiX, which calls such a run athermal); where the two differ (first
/// row above 0) the choice is warned about, and the calculix dialect keeps
/// only the first row.
void apply_temperature_table_dialect(DeckState& state);
// output_keywords.cpp
TETHER_DECK_HANDLER(handle_node_print);
TETHER_DECK_HANDLER(handle_el_print);
TETHER_DECK_HANDLER(handle_node_file);
TETHER_DECK_HANDLER(handle_el_file);
TETHER_DECK_HANDLER(handle_output);
TETHER_DECK_HANDLER(handle_node_output);
TETHER_DECK_HANDLER(handle_element_output);
TETHER_DECK_HANDLER(handle_equation);
TETHER_DECK_HANDLER(handle_mpc);
TETHER_DECK_HANDLER(handle_constraint);
TETHER_DECK_HANDLER(handle_surface_interaction);
TETHER_DECK_HANDLER(handle_surface_behavior);
TETHER_DECK_HANDLER(handle_friction);
TETHER_DECK_HANDLER(handle_contact_pair);
TETHER_DECK_HANDLER(handle_contact_output);
// tie_keywords.cpp
TETHER_DECK_HANDLER(handle_tie);
TETHER_DECK_HANDLER(handle_periodic);
// pretension_keywords.cpp
TETHER_DECK_HANDLER(handle_pre_tension_section);

#undef TETHER_DECK_HANDLER

/// After the whole deck: no step prescribes or loads a pretension node's dof
/// other than 1 (InputError at that line). In pretension_keywords.cpp.
void check_pretension_loads(const DeckState& state);

}  // namespace tether::deck
