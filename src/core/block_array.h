// An array that grows in fixed blocks instead of reallocating: appending never copies what is
// there, so a parse that does not know its final size holds its data once (plus at most one
// block), never the old and the new copy of a doubled vector at once. Random access stays O(1).
// release() hands the elements over as one exactly sized vector, freeing each block once copied.
#pragma once

#include <algorithm>
#include <cstddef>
#include <memory>
#include <utility>
#include <vector>

namespace reflect {

template <class T>
class BlockArray {
 public:
  static constexpr size_t kShift = 14;
  static constexpr size_t kBlock = size_t{1} << kShift;  // elements a block
  static constexpr size_t kMask = kBlock - 1;

  size_t size() const { return size_; }
  bool empty() const { return size_ == 0; }
  T& operator[](size_t i) { return blocks_[i >> kShift][i & kMask]; }
  const T& operator[](size_t i) const { return blocks_[i >> kShift][i & kMask]; }

  void push_back(const T& value) {
    const size_t block = size_ >> kShift;
    const size_t offset = size_ & kMask;
    if (block == 0 && offset == firstCapacity_) growFirst();
    if (offset == 0 && block > 0 && block == blocks_.size()) {
      blocks_.push_back(std::make_unique<T[]>(kBlock));
    }
    blocks_[block][offset] = value;
    ++size_;
  }

  // Bytes allocated for the elements (the memory this array holds).
  size_t capacityBytes() const {
    if (blocks_.empty()) return 0;
    return (firstCapacity_ + (blocks_.size() - 1) * kBlock) * sizeof(T);
  }

  void clear() {
    blocks_.clear();
    blocks_.shrink_to_fit();
    size_ = 0;
    firstCapacity_ = 0;
  }

  // The elements as one vector of exactly size() elements, each converted by `convert(i, element)`;
  // the array is empty afterwards. Each block is freed as soon as it is copied.
  template <class U, class Convert>
  std::vector<U> release(Convert convert) {
    std::vector<U> out;
    out.reserve(size_);
    for (size_t i = 0; i < size_; ++i) {
      out.push_back(convert(i, (*this)[i]));
      if ((i & kMask) == kMask) blocks_[i >> kShift].reset();
    }
    clear();
    return out;
  }
  std::vector<T> release() {
    return release<T>([](size_t, const T& value) { return value; });
  }

 private:
  // The first block starts small and doubles up to a whole block, so a tiny mesh does not pay
  // for a full block of every array.
  void growFirst() {
    const size_t capacity = firstCapacity_ == 0 ? 64 : std::min(firstCapacity_ * 2, kBlock);
    auto grown = std::make_unique<T[]>(capacity);
    for (size_t i = 0; i < size_; ++i) grown[i] = std::move(blocks_[0][i]);
    if (blocks_.empty()) {
      blocks_.push_back(std::move(grown));
    } else {
      blocks_[0] = std::move(grown);
    }
    firstCapacity_ = capacity;
  }

  std::vector<std::unique_ptr<T[]>> blocks_;
  size_t size_ = 0;
  size_t firstCapacity_ = 0;
};

}  // namespace reflect
