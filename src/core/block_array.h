// An array that grows in blocks instead of reallocating: appending never copies what is there, so
// a parse that does not know its final size holds its data once (plus at most one block), never
// the old and the new copy of a doubled vector at once. Random access stays O(1). release() hands
// the elements over as one exactly sized vector, freeing each block once copied.
//
// The blocks double from kFirst elements up to kBlock, then stay at kBlock, so a tiny mesh does
// not pay for a full block of every array. No block is freed before the array is (a first block
// that grew by reallocation would leave its smaller predecessors behind as gaps): arrays filled
// one after the other lie side by side, with no gaps for another array's blocks to fall into, and
// when they are freed together the space they leave is one piece. The OBJ parser relies on it
// (obj_vertices.cpp: the positions and normals, read before the faces, leave the space the index
// array is then copied into).
#pragma once

#include <algorithm>
#include <bit>
#include <cstddef>
#include <memory>
#include <utility>
#include <vector>

namespace reflect {

template <class T>
class BlockArray {
 public:
  static constexpr size_t kFirstShift = 6;
  static constexpr size_t kFirst = size_t{1} << kFirstShift;  // elements of the first block
  static constexpr size_t kShift = 12;
  static constexpr size_t kBlock = size_t{1} << kShift;  // elements of each full-sized block
  static constexpr size_t kMask = kBlock - 1;
  // Blocks before the first full-sized one: kFirst elements, then kFirst, 2 kFirst, ...,
  // kBlock / 2 (each as large as all before it), kBlock elements in all.
  static constexpr size_t kGrowing = kShift - kFirstShift + 1;

  size_t size() const { return size_; }
  bool empty() const { return size_ == 0; }
  T& operator[](size_t i) { return element(i); }
  const T& operator[](size_t i) const { return const_cast<BlockArray*>(this)->element(i); }

  void push_back(const T& value) {
    if (size_ == capacity_) {
      const size_t grown = blockSize(blocks_.size());
      blocks_.push_back(std::make_unique<T[]>(grown));
      capacity_ += grown;
    }
    element(size_) = value;
    ++size_;
  }

  // Bytes allocated for the elements (the memory this array holds).
  size_t capacityBytes() const { return capacity_ * sizeof(T); }

  // Keeps the first `count` elements (count <= size()), freeing the blocks past them.
  void truncate(size_t count) {
    while (!blocks_.empty() && capacity_ - blockSize(blocks_.size() - 1) >= count) {
      capacity_ -= blockSize(blocks_.size() - 1);
      blocks_.pop_back();
    }
    size_ = count;
  }

  void clear() {
    blocks_.clear();
    blocks_.shrink_to_fit();
    size_ = 0;
    capacity_ = 0;
  }

  // The elements as one vector of exactly size() elements; the array is empty afterwards. Each
  // block is freed as soon as it is copied.
  std::vector<T> release() {
    std::vector<T> out;
    out.reserve(size_);
    for (size_t b = 0; out.size() < size_; ++b) {
      const size_t count = std::min(blockSize(b), size_ - out.size());
      out.insert(out.end(), blocks_[b].get(), blocks_[b].get() + count);
      blocks_[b].reset();
    }
    clear();
    return out;
  }

 private:
  static size_t blockSize(size_t b) {
    if (b >= kGrowing) return kBlock;
    return b == 0 ? kFirst : kFirst << (b - 1);
  }

  // Element i: in a full-sized block past the first kBlock elements; before them, in the growing
  // block whose size is i's highest bit (the first kFirst elements in block 0).
  T& element(size_t i) {
    if (i >= kBlock) return blocks_[(i >> kShift) + kGrowing - 1][i & kMask];
    if (i < kFirst) return blocks_[0][i];
    const size_t high = static_cast<size_t>(std::bit_width(i)) - 1;  // kFirstShift..kShift - 1
    return blocks_[high - kFirstShift + 1][i - (size_t{1} << high)];
  }

  std::vector<std::unique_ptr<T[]>> blocks_;
  size_t size_ = 0;
  size_t capacity_ = 0;
};

}  // namespace reflect
