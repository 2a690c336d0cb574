#pragma once
/// \file The terms of 2D mortar contact, one per (slave face e, master face
/// f), and the pair's memo of them.
///
/// The weighted gap g̃_j of slave node j sums the terms of the slave faces
/// around j against the master faces they overlap (mortar_node.hpp). One
/// segment integration of face e against face f gives the term of every node
/// of e at once: its value, and with Dual2 its gradient and Hessian over the
/// positions of the term's nodes (the nodes of e, of the slave faces around
/// them, whose normals enter, and of f). Computed per node, each term was
/// integrated once for each node of its face (twice for linear faces, three
/// times for quadratic ones); the memo integrates it once per face pair and
/// state and hands every node of e its share. Each share is the same
/// arithmetic as before, so the same bits.
///
/// A term is a pure function of the positions of its nodes (and, with
/// friction, of their positions at the start of the increment), of the
/// derivative order and of the measure (NLGEOM or not): the memo keys each
/// entry on exactly those, bit for bit, so it never hands out a stale term.

#include <Eigen/Core>
#include <array>
#include <functional>
#include <mutex>
#include <vector>

#include "tether/assembly/contribution.hpp"
#include "tether/contact/mortar_segmentation.hpp"

namespace tether {

class MortarPair;

/// One term of the mortar kinematics of slave node j (position k on slave
/// face e) against master face f: D = D^e_kf (the part of D^e_k over the
/// overlap with f), M_a = M^e_kfa, the nodal normal n_j, and the weighted gap
/// vector v = Σ_a M_a y_a - D x_j, whose normal part n_j·v is the term's
/// share of g̃_j.
template <class T>
struct MortarTerm {
  /// User-provided, so that `std::vector<MortarTerm<Dual2>>(n)` does not
  /// zero every Dual2's in-place storage first (value-initialization of a
  /// class without one zero-fills it: about 50 kB per term).
  MortarTerm() {}  // NOLINT(modernize-use-equals-default): see above
  bool overlaps = false;
  T D{};
  std::array<T, 3> M{};
  Vec2T<T> normal{}, v{};
  std::vector<Vec2T<T>> y;  ///< master face positions
  Vec2T<T> x_j{};
};

/// A scalar of a term with its derivatives over the term's unknowns (x and y
/// of each of its nodes, MortarFaceTerms::nodes order): a Dual2's value,
/// gradient and Hessian, stored at their size.
struct MortarTermScalar {
  double value = 0;
  Eigen::VectorXd gradient;  ///< empty: a constant
  Eigen::MatrixXd hessian;   ///< empty: first order (or a constant)
  MortarTermScalar() = default;
  explicit MortarTermScalar(const Dual2& d);
  [[nodiscard]] bool constant() const { return gradient.size() == 0; }
  [[nodiscard]] bool second() const { return hessian.size() > 0; }
};

/// What the kinematics of node k of the face take from a term with
/// derivatives (order >= 1).
struct MortarTermShare {
  bool overlaps = false;
  MortarTermScalar gap;  ///< n_j·v (overlapping terms)
  MortarTermScalar D;    ///< D^e_kf (overlapping terms)
  /// With friction: the term's share of the weighted slip increment,
  /// τ_j·(v - v⁰) (v⁰ from the integrals at the start of the increment).
  MortarTermScalar slip;
  /// With friction and overlapping: the frictional direction's entries
  /// D τ_x, D τ_y (at x_j), then -M_a τ_x, -M_a τ_y per master node a.
  std::vector<MortarTermScalar> G;
};

/// The terms of one slave face against one master face at one state.
struct MortarFaceTerms {
  std::vector<int> nodes;  ///< the real nodes the terms depend on (term nodes)
  /// Order 0: per position k on the face, the term (values) and, with
  /// friction, the term at the start of the increment.
  std::vector<MortarTerm<double>> values, start;
  std::vector<MortarTermShare> shares;  ///< order >= 1: per position k
};

/// The pair's memo of terms: per (slave face, master face) and order class
/// (0; 1; 2), the last state's terms; the entries of master faces a slave
/// face no longer sums (MortarPair::term_faces) are dropped at its next
/// look-up, so the memo stays the size of the current terms. Thread-safe.
class MortarTermCache {
 public:
  /// Calls `use` with the terms of slave face e against master face f at
  /// `state` (order 0: values; 1: gradients; 2: gradients and Hessians;
  /// `friction`: with the start-of-increment terms and the slip and
  /// frictional direction shares), computing them unless the memo holds
  /// them for the same positions. `use` runs under the memo's lock.
  void with_terms(const MortarPair& pair, int e, int f, const EvaluationState& state, int order, bool friction,
                  const std::function<void(const MortarFaceTerms&)>& use);
  /// Number of (slave face, master face) entries held.
  [[nodiscard]] std::size_t size();

 private:
  struct Slot {
    bool valid = false, nlgeom = false, friction = false;
    std::vector<Vec2T<double>> x, x0;  ///< positions of the term nodes (x0: at the start, with friction)
    MortarFaceTerms terms;
  };
  struct Entry {
    int f = -1;
    std::vector<int> nodes;     ///< mortar_term_nodes(e, f)
    int n_slave = 0;            ///< the first n_slave of `nodes` are slave nodes (the same for every f)
    std::array<Slot, 3> slots;  ///< by order
  };
  /// The nodal normals (Dual2) of one slave face's nodes, for its terms
  /// against every master face it sums: they depend only on the slave nodes,
  /// which lead every term's unknowns of the face in the same order, so for
  /// terms with the same number of unknowns they are the same bits. Keyed on
  /// the face, the number of unknowns, the derivative order and the slave
  /// nodes' positions.
  struct NormalSlot {
    int e = -1, n = 0;
    bool second = false;
    std::vector<Vec2T<double>> x;  ///< positions of the slave nodes
    std::vector<Vec2T<Dual2>> normals;
  };
  /// The normals of slave face e for a term over `nodes` at positions `x`
  /// (order 1: gradients, 2: and Hessians), from the slots or computed.
  const std::vector<Vec2T<Dual2>>& face_normals(const MortarPair& pair, int e, const Entry& entry,
                                                const std::vector<Vec2T<double>>& x, int order);
  std::mutex mutex_;
  std::vector<std::vector<Entry>> entries_;  ///< by slave face
  std::array<NormalSlot, 4> normal_slots_;   ///< the last faces' normals (a few: bounded memory)
  std::size_t next_normal_slot_ = 0;
};

/// The real nodes one term (slave face e, master face f) depends on: the
/// nodes of e, of the slave faces around them (their normals), and of f;
/// `n_slave` (when given): how many of them, first, are slave nodes.
std::vector<int> mortar_term_nodes(const MortarPair& pair, int e, int f, int* n_slave = nullptr);

/// Current position of node n (reference + displacement in u).
Vec2T<double> mortar_position(const MortarPair& pair, const Eigen::VectorXd& u, int n);

}  // namespace tether
