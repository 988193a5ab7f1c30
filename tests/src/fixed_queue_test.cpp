#include "src/fixed_queue.h"

#include <gtest/gtest.h>

#include <vector>

namespace colav {
namespace {

std::vector<int> Contents(FixedQueue<int>& queue) {
  std::vector<int> values;
  for (int k = 0; k < queue.size(); ++k) values.push_back(queue[k]);
  return values;
}

TEST(FixedQueue, KeepsFirstInFirstOutAcrossTheRingsEnd) {
  FixedQueue<int> queue(3);
  for (const int value : {1, 2, 3}) queue.Push(value);
  EXPECT_EQ(queue.Pop(), 1);
  queue.Push(4);  // stored where 1 was
  EXPECT_EQ(Contents(queue), (std::vector<int>{2, 3, 4}));
  EXPECT_EQ(queue.Pop(), 2);
  queue.Push(5);
  EXPECT_EQ(Contents(queue), (std::vector<int>{3, 4, 5}));
}

TEST(FixedQueue, RemovingFromTheMiddleKeepsTheOthersInOrder) {
  FixedQueue<int> queue(4);
  for (const int value : {7, 8, 9}) queue.Push(value);
  EXPECT_EQ(queue.Pop(), 7);
  for (const int value : {10, 11}) queue.Push(value);  // the last one wraps round
  EXPECT_EQ(queue.Remove(2), 10);
  EXPECT_EQ(Contents(queue), (std::vector<int>{8, 9, 11}));
  EXPECT_EQ(queue.Remove(2), 11);
  EXPECT_EQ(Contents(queue), (std::vector<int>{8, 9}));
  queue.Clear();
  EXPECT_EQ(queue.size(), 0);
  queue.Push(12);
  EXPECT_EQ(Contents(queue), (std::vector<int>{12}));
}

}  // namespace
}  // namespace colav
