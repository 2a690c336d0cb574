#pragma once
/// \file The reader's working state while keyword handlers run, and the
/// lookups they share (nodes, elements, sets, amplitudes by label or name).

#include <map>
#include <string>
#include <string_view>
#include <unordered_map>
#include <vector>

#include "tether/io/deck_reader.hpp"
#include "tether/io/line_reader.hpp"
#include "tether/model/model.hpp"

namespace tether::deck {

/// Everything the keyword handlers read and write.
struct DeckState {
  Model model;
  std::vector<DeckWarning>* warnings = nullptr;

  // --- position in the deck ---
  int material = -1;         ///< material being defined (material options allowed), else -1
  int interaction = -1;      ///< surface interaction being defined (its options allowed), else -1
  bool in_step = false;      ///< between *STEP and *END STEP
  bool seen_step = false;    ///< a *STEP has been read (model data is over)
  bool step_has_procedure = false;
  bool step_amplitude_given = false;  ///< the current *STEP wrote AMPLITUDE=

  // --- history data in force (OP=MOD/NEW resolved), copied into each step at *END STEP ---
  std::vector<Prescribed> boundary;
  std::vector<ConcentratedLoad> cloads;
  std::vector<PressureLoad> dloads;   ///< from *DLOAD
  std::vector<PressureLoad> dsloads;  ///< from *DSLOAD
  std::vector<BodyLoad> body_loads;   ///< from *DLOAD GRAV / CENTRIF
  Controls controls;                  ///< carried from step to step until *CONTROLS, RESET
  int restart_frequency = 0;          ///< *RESTART, WRITE in force (0 = none), carried to later steps
  /// Dialect calculix: CalculiX's one FREQUENCY of all print requests
  /// (*NODE PRINT, *EL PRINT, *CONTACT PRINT): the last one given on any of
  /// them, carried to later steps (1 until one is given).
  int print_frequency = 1;
  bool print_frequency_given = false;  ///< some print request gave FREQUENCY (this step or an earlier one)
  /// Indices into the current step's outputs of its *NODE PRINT, *EL PRINT
  /// and *CONTACT PRINT requests (not *OUTPUT, HISTORY ones), cleared at *END STEP.
  std::vector<std::size_t> print_requests;
  /// Kinds ("BOUNDARY", "CLOAD", ...) already cleared by OP=NEW in the current step.
  std::vector<std::string> cleared_this_step;

  // --- *OUTPUT block (for *NODE OUTPUT / *ELEMENT OUTPUT) ---
  bool output_active = false;
  bool output_field = true;  ///< FIELD (file) or HISTORY (print)
  /// The block's FREQUENCY / NUMBER INTERVAL / TIME INTERVAL / TIME MARKS
  /// (kind, set and variables unused), copied into its requests.
  OutputRequest output_schedule;

  // --- line elements (T2D2/T2D3/T3D2/T3D3, as Gmsh writes physical curves) ---
  /// A line element: no stiffness and not part of the model; it only names the
  /// faces of the solid elements it lies on (*SURFACE, TYPE=ELEMENT).
  struct LineElement {
    int id = 0;              ///< user label (shares the label space of *ELEMENT)
    std::vector<int> nodes;  ///< node indices: two corners, then the mid-side node of T*D3
    std::string type;        ///< as written, upper case
    SourceLocation where;
  };
  std::vector<LineElement> lines;
  std::unordered_map<int, int> line_index;                 ///< label -> index into `lines`
  std::map<std::string, std::vector<int>> line_sets;       ///< line members of element sets (indices into `lines`)

  // --- resolved after the whole deck is read ---
  std::vector<std::string> section_material;  ///< material name of each section (upper case)

  /// Records a warning.
  void warn(const SourceLocation& where, std::string message) const;

  /// The step being read (precondition: in_step).
  Step& step() { return model.steps.back(); }

  /// Node index of a label; InputError "undefined node N" otherwise.
  [[nodiscard]] int node(int label, const SourceLocation& where) const;
  /// Element index of a label; InputError "undefined element N" otherwise.
  [[nodiscard]] int element(int label, const SourceLocation& where) const;
  /// Node indices of a data token: a node label or the name of a node set.
  [[nodiscard]] std::vector<int> nodes_of(std::string_view token, const SourceLocation& where) const;
  /// Element indices of a data token: an element label or the name of an element set.
  [[nodiscard]] std::vector<int> elements_of(std::string_view token, const SourceLocation& where) const;
  /// Members of a named node set (upper-cased); InputError if undefined.
  [[nodiscard]] const std::vector<int>& node_set(std::string_view name, const SourceLocation& where) const;
  /// Members of a named element set (upper-cased); InputError if undefined.
  [[nodiscard]] const std::vector<int>& element_set(std::string_view name, const SourceLocation& where) const;
  /// True when `token` is the label of a line element or the name of a set holding line elements.
  [[nodiscard]] bool names_lines(std::string_view token) const;
  /// Line-element indices of a data token (label or set name); empty when it names none.
  [[nodiscard]] std::vector<int> lines_of(std::string_view token) const;
  /// Amplitude index by name, -1 for an empty name; InputError if undefined.
  [[nodiscard]] int amplitude(std::string_view name, const SourceLocation& where) const;
};

/// Fields of a data line, with at least `min_fields` of them (InputError
/// "expected <what>" otherwise) and at most `max_fields` (0 = no limit).
std::vector<std::string> data_fields(const DataLine& line, std::size_t min_fields, std::size_t max_fields,
                                     std::string_view what);

/// Throws InputError at the keyword line when the block has no data line.
void require_data(const KeywordBlock& block, std::string_view what);

/// Face id `<prefix>1..<prefix>n` ("S2", "P3"; case-insensitive) of element
/// `e` of `model`, returned 0-based; InputError naming the element as the
/// user knows it (label_text()) and the allowed range otherwise.
int parse_face_id(const std::string& token, const Model& model, const Element& e, const SourceLocation& at,
                  char prefix);

/// Sorts and removes duplicates.
void sort_unique(std::vector<int>& v);

/// A FREQUENCY given on a print request (*NODE PRINT, *EL PRINT, *CONTACT
/// PRINT): in the calculix dialect it becomes the one print frequency of the
/// step and of later steps (DeckState::print_frequency, applied at *END STEP).
inline void note_print_frequency(DeckState& state, int frequency) {
  if (frequency >= 0) state.print_frequency = frequency, state.print_frequency_given = true;
}

}  // namespace tether::deck
