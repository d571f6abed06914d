#include "learning/q_table.hpp"

#include <gtest/gtest.h>

#include "common/checkpoint_stream.hpp"

#include <vector>

namespace crux {
namespace {

TEST(QTable, UnwrittenValuesAndVisitsAreZero) {
  const QTable q(4);
  EXPECT_EQ(q.action_count(), 4);
  EXPECT_EQ(q.state_count(), 0u);
  EXPECT_EQ(q.value(17, 3), 0.0) << "every Q-table starts at 0 (docs/MODEL.md, choice C18)";
  EXPECT_EQ(q.visits(17, 3), 0u);
  EXPECT_FALSE(q.taken(17, 3));
}

TEST(QTable, StoresEachPairsValueApart) {
  QTable q(3);
  q.set_value(5, 0, -1.5);
  q.set_value(5, 2, 42.25);
  q.set_value(6, 0, 7.0);
  EXPECT_EQ(q.value(5, 0), -1.5);
  EXPECT_EQ(q.value(5, 1), 0.0) << "the other actions of a new row start at 0";
  EXPECT_EQ(q.value(5, 2), 42.25);
  EXPECT_EQ(q.value(6, 0), 7.0);
  EXPECT_EQ(q.value(6, 2), 0.0);
  q.set_value(5, 2, -3.0);
  EXPECT_EQ(q.value(5, 2), -3.0) << "a write replaces the value";
  EXPECT_EQ(q.state_count(), 2u);
}

TEST(QTable, VisitsCountUpAndCanBeSet) {
  QTable q(2);
  q.add_visit(3, 1);
  q.add_visit(3, 1);
  q.add_visit(3, 1);
  EXPECT_EQ(q.visits(3, 1), 3u);
  EXPECT_EQ(q.visits(3, 0), 0u);
  EXPECT_TRUE(q.taken(3, 1));
  EXPECT_FALSE(q.taken(3, 0));
  EXPECT_EQ(q.value(3, 1), 0.0) << "a visit leaves the value alone";
  q.set_visits(3, 1, 0);
  EXPECT_FALSE(q.taken(3, 1)) << "set_visits replaces the count";
  q.set_visits(8, 0, 4000000000u);
  EXPECT_EQ(q.visits(8, 0), 4000000000u);
  q.add_visit(8, 0);
  EXPECT_EQ(q.visits(8, 0), 4000000001u);
}

TEST(QTable, BestValueIsTheMaximumOverTheAvailableActionsOnly) {
  QTable q(5);
  q.set_value(1, 0, -10.0);
  q.set_value(1, 1, -2.0);
  q.set_value(1, 2, 100.0);  // the largest, but offered only in the last query
  q.set_value(1, 3, -7.0);
  // Action 4 is unwritten: 0.
  EXPECT_EQ(q.best_value(1, std::vector<ActionCode>{0, 1, 3}), -2.0);
  EXPECT_EQ(q.best_value(1, std::vector<ActionCode>{3, 0}), -7.0) << "order of the subset does not matter";
  EXPECT_EQ(q.best_value(1, std::vector<ActionCode>{0}), -10.0) << "a single negative action is its own max";
  EXPECT_EQ(q.best_value(1, std::vector<ActionCode>{0, 4}), 0.0) << "an unwritten action counts as 0";
  EXPECT_EQ(q.best_value(1, std::vector<ActionCode>{0, 1, 2, 3, 4}), 100.0);
}

TEST(QTable, BestValueIsZeroWhenNothingIsAvailableOrTheStateIsUnseen) {
  QTable q(2);
  q.set_value(1, 0, -50.0);
  q.set_value(1, 1, -60.0);
  EXPECT_EQ(q.best_value(1, std::vector<ActionCode>{}), 0.0) << "not the row's -50";
  EXPECT_EQ(q.best_value(2, std::vector<ActionCode>{0, 1}), 0.0);
  EXPECT_EQ(q.state_count(), 1u) << "a query creates no row";
}

TEST(QTable, RowsAreCreatedOnlyByWrites) {
  QTable q(3);
  (void)q.value(1, 0);
  (void)q.visits(2, 0);
  (void)q.taken(3, 0);
  (void)q.best_value(4, std::vector<ActionCode>{0, 1});
  EXPECT_EQ(q.state_count(), 0u) << "reads leave the table empty";
  q.set_value(10, 1, 0.0);
  EXPECT_EQ(q.state_count(), 1u) << "writing a 0 still creates the row";
  q.add_visit(11, 0);
  q.set_visits(12, 2, 0);
  EXPECT_EQ(q.state_count(), 3u);
  q.set_value(10, 2, 1.0);
  q.add_visit(11, 1);
  EXPECT_EQ(q.state_count(), 3u) << "a second write to a row adds none";
}

TEST(QTable, ForEachRowVisitsRowsInIncreasingStateOrderWithTheirWholeRow) {
  QTable q(3);
  // Written in neither increasing nor decreasing order (a hash map could give back
  // either), with a state large enough to need 64 bits.
  const StateCode big = 0xFFFF'FFFF'FFFF'0000ULL;
  q.set_value(40, 0, -1.0);
  q.add_visit(40, 1);
  q.set_value(big, 2, 9.0);
  q.add_visit(7, 2);
  q.set_value(7, 0, 0.5);
  q.set_value(1000, 1, 2.0);
  q.set_visits(3, 0, 5);
  std::vector<StateCode> order;
  std::vector<std::vector<double>> values;
  std::vector<std::vector<std::uint32_t>> visits;
  q.for_each_row([&](StateCode s, std::span<const double> v, std::span<const std::uint32_t> n) {
    order.push_back(s);
    values.emplace_back(v.begin(), v.end());
    visits.emplace_back(n.begin(), n.end());
  });
  ASSERT_EQ(order, (std::vector<StateCode>{3, 7, 40, 1000, big}));
  EXPECT_EQ(values[0], (std::vector<double>{0.0, 0.0, 0.0}));
  EXPECT_EQ(visits[0], (std::vector<std::uint32_t>{5, 0, 0}));
  EXPECT_EQ(values[1], (std::vector<double>{0.5, 0.0, 0.0}));
  EXPECT_EQ(visits[1], (std::vector<std::uint32_t>{0, 0, 1}));
  EXPECT_EQ(values[2], (std::vector<double>{-1.0, 0.0, 0.0}));
  EXPECT_EQ(visits[2], (std::vector<std::uint32_t>{0, 1, 0}));
  EXPECT_EQ(values[3], (std::vector<double>{0.0, 2.0, 0.0}));
  EXPECT_EQ(values[4], (std::vector<double>{0.0, 0.0, 9.0}));
  EXPECT_EQ(visits[4], (std::vector<std::uint32_t>{0, 0, 0}));
}

TEST(QTable, ForEachRowOnAnEmptyTableVisitsNothing) {
  const QTable q(2);
  int rows = 0;
  q.for_each_row([&](StateCode, auto, auto) { ++rows; });
  EXPECT_EQ(rows, 0);
}

TEST(QTable, CopiesAreIndependent) {
  // A transferred Q_grid is a copy of the training run's: learning on it must not
  // change the original.
  QTable original(2);
  original.set_value(1, 0, 3.0);
  QTable copy = original;
  copy.set_value(1, 0, -3.0);
  copy.set_value(2, 1, 1.0);
  EXPECT_EQ(original.value(1, 0), 3.0);
  EXPECT_EQ(original.state_count(), 1u);
  EXPECT_EQ(copy.state_count(), 2u);
}

TEST(QTable, ACheckpointRestoresValuesVisitsAndRowOrder) {
  QTable table(3);
  table.set_value(9, 1, 2.5);
  table.add_visit(4, 2);
  table.set_value(7, 0, -1.0 / 3.0);
  CheckpointWriter out;
  table.save_state(out);
  const std::string bytes = out.take();
  QTable restored(3);
  restored.set_value(1, 1, 8.0);  // replaced
  CheckpointReader in(bytes, "test");
  restored.load_state(in);
  EXPECT_TRUE(in.at_end());
  EXPECT_EQ(restored.state_count(), 3u);
  EXPECT_EQ(restored.value(9, 1), 2.5);
  EXPECT_EQ(restored.value(7, 0), -1.0 / 3.0);
  EXPECT_EQ(restored.visits(4, 2), 1u);
  EXPECT_EQ(restored.value(1, 1), 0.0);
  // Saved again, the restored table gives the same bytes: rows keep their order.
  CheckpointWriter again;
  restored.save_state(again);
  EXPECT_EQ(again.take(), bytes);
  QTable other_width(4);
  CheckpointReader wrong(bytes, "test");
  EXPECT_ANY_THROW(other_width.load_state(wrong));
}

}  // namespace
}  // namespace crux
