#pragma once
/// @file Islands.h
/// @brief Groups contacts into islands: sets of movable bodies linked by contacts.

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <span>
#include <utility>
#include <vector>

namespace thyrix {

/// Union-find over movable bodies, then a counting sort of the contacts by island. Fixed
/// bodies do not link islands (they never move). Islands come out in order of their first
/// contact and list their contacts in increasing order, so the result is reproducible.
///
/// The rows are given one by one while the caller visits them (start(), then the Adder's
/// addBody() and addRow(), then finish()), so that the caller's pass over its contacts also
/// links the islands. Sets are joined by rank (the shallower tree under the deeper root), so
/// that a root is a step or two away: the search for it then mostly ends at a predictable
/// test. Which body is a root does not show in the result.
class Islands {
  static constexpr std::uint32_t none = ~0u;

 public:
  /// Adds bodies and rows to the grouping start() began, through plain pointers (a caller's
  /// loop keeps them in registers, whatever it stores meanwhile).
  class Adder {
   public:
    /// Adds body @p body, alone so far (each body a row names, once, before its first row).
    void addBody(std::uint32_t body) {
      parent_[body] = body;
      rank_[body] = 0;
      islandOfBody_[body] = none;
    }
    /// Adds row @p k (rows in increasing order, from 0) between bodies @p a and @p b, whether
    /// each can move given by @p movableA and @p movableB.
    void addRow(std::size_t k, std::uint32_t a, std::uint32_t b, bool movableA, bool movableB) {
      // The body whose island the row joins; its root is looked up in finish().
      islandOfRow_[k] = movableA ? a : b;
      if (movableA && movableB) link(a, b);
    }

   private:
    friend class Islands;
    Adder(std::uint32_t* parent, std::uint8_t* rank, std::uint32_t* islandOfBody,
          std::uint32_t* islandOfRow)
        : parent_(parent), rank_(rank), islandOfBody_(islandOfBody), islandOfRow_(islandOfRow) {}
    /// Joins the sets of bodies @p a and @p b: the root of lesser rank goes under the other
    /// (ties: B's under A's, and A's rank grows). Without a branch: whether the two are
    /// already one set is unpredictable (in a pile, a test was mispredicted every other
    /// contact); for one set the stores change nothing (a root is its own parent).
    void link(std::uint32_t a, std::uint32_t b) {
      const std::uint32_t rootA = find(parent_, halve(a));
      const std::uint32_t rootB = find(parent_, halve(b));
      const std::uint8_t rankA = rank_[rootA];
      const std::uint8_t rankB = rank_[rootB];
      const bool swapped = rankA < rankB;
      const std::uint32_t root = swapped ? rootB : rootA;
      const std::uint32_t child = swapped ? rootA : rootB;
      parent_[child] = root;
      rank_[root] = static_cast<std::uint8_t>(std::max(rankA, rankB) +
                                              (rankA == rankB && rootA != rootB ? 1 : 0));
    }

    /// The first step of find()'s halving, without its test: @p body's grandparent, now its
    /// parent. At a root or a root's child it changes nothing (a root is its own parent).
    /// While sets are linked most bodies are that close to their root, so find()'s test then
    /// fails at once, predictably: in a pile, where a body sat one step deeper or not was
    /// mispredicted about once a contact. (Once linked, finish() has the trees flat: there it
    /// would be extra work.)
    std::uint32_t halve(std::uint32_t body) {
      const std::uint32_t grandparent = parent_[parent_[body]];
      parent_[body] = grandparent;
      return grandparent;
    }

    std::uint32_t* parent_;
    std::uint8_t* rank_;
    std::uint32_t* islandOfBody_;
    std::uint32_t* islandOfRow_;
  };

  /// Begins a grouping of @p rows rows among up to @p bodies bodies; @return what adds them.
  Adder start(std::size_t bodies, std::size_t rows);
  /// Numbers the islands and sorts by island the rows added since start().
  void finish();

  /// Makes room for @p bodies bodies and @p rows contacts without further allocation.
  void reserve(std::size_t bodies, std::size_t rows);
  /// Number of islands found by the last finish().
  [[nodiscard]] std::size_t count() const { return islandCount_; }
  /// The contact indices of island @p i.
  [[nodiscard]] std::span<const std::uint32_t> island(std::size_t i) const {
    return std::span(contacts_).subspan(islandStart_[i], islandStart_[i + 1] - islandStart_[i]);
  }

 private:
  /// The root of @p body's set in the forest @p parent, halving the path on the way.
  static std::uint32_t find(std::uint32_t* parent, std::uint32_t body) {
    while (parent[body] != body) {
      parent[body] = parent[parent[body]];  // path halving
      body = parent[body];
    }
    return body;
  }

  std::vector<std::uint32_t> parent_;        // union-find forest over bodies
  std::vector<std::uint8_t> rank_;           // of each root: at most log2 of its set's size
  std::vector<std::uint32_t> islandOfBody_;  // dense island number of each root, or none
  std::vector<std::uint32_t> islandOfRow_;   // a body of each row, then its island
  std::vector<std::uint32_t> islandStart_;   // where each island starts in contacts_, and the end
  std::size_t islandCount_ = 0;
  std::vector<std::uint32_t> contacts_;
};

}  // namespace thyrix
