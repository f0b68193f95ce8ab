// Which rows of the picture one processor renders (paper section 2.3): "partition the
// picture into N parts" (blocks: N bands of consecutive rows, the load follows where the
// patches are) or, after Feda, every N-th scanline (scanlines: an even load).
#pragma once

#include <string>

namespace ncube {

enum class RowPartition { kBlocks, kScanlines };

// "blocks" or "scanlines".
const char* row_partition_name(RowPartition partition);

struct RowShare {
  int height = 0;  // rows of the picture
  int parts = 1;   // N, the processors sharing it
  int part = 0;    // this processor's part, 0 .. N-1
  RowPartition partition = RowPartition::kBlocks;

  // The whole picture (the sequential render).
  static RowShare whole(int height) { return {height, 1, 0, RowPartition::kBlocks}; }

  // Blocks: part p holds rows [height p / N, height (p+1) / N) (sizes differ by at most one).
  int block_begin() const { return int(long(height) * part / parts); }
  int block_end() const { return int(long(height) * (part + 1) / parts); }

  bool owns(int row) const;
  int count() const;             // rows owned
  int local_index(int row) const;  // 0 .. count()-1 for an owned row
  int row_at(int local) const;     // the inverse
  // The first owned row >= row (height if none), and the step to the next owned row after
  // it: consecutive rows for blocks, N rows for scanlines.
  int first_owned_from(int row) const;
  int next_owned(int row) const;
};

}  // namespace ncube
