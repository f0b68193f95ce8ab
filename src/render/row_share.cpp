#include "render/row_share.h"

namespace ncube {

const char* row_partition_name(RowPartition partition) {
  return partition == RowPartition::kBlocks ? "blocks" : "scanlines";
}

bool RowShare::owns(int row) const {
  if (row < 0 || row >= height) return false;
  return partition == RowPartition::kBlocks ? row >= block_begin() && row < block_end()
                                            : row % parts == part;
}

int RowShare::count() const {
  if (partition == RowPartition::kBlocks) return block_end() - block_begin();
  return part < height ? (height - 1 - part) / parts + 1 : 0;
}

int RowShare::local_index(int row) const {
  return partition == RowPartition::kBlocks ? row - block_begin() : row / parts;
}

int RowShare::row_at(int local) const {
  return partition == RowPartition::kBlocks ? block_begin() + local : local * parts + part;
}

int RowShare::first_owned_from(int row) const {
  if (row < 0) row = 0;
  if (partition == RowPartition::kBlocks) {
    if (row < block_begin()) row = block_begin();
    return row < block_end() ? row : height;
  }
  const int offset = ((part - row) % parts + parts) % parts;
  return row + offset < height ? row + offset : height;
}

int RowShare::next_owned(int row) const {
  const int next = partition == RowPartition::kBlocks ? row + 1 : row + parts;
  return owns(next) ? next : height;
}

}  // namespace ncube
