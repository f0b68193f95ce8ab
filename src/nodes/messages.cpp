#include "nodes/messages.h"

#include <stdexcept>

#include "nodes/render_setup.h"

namespace ncube {

double part_mask_bytes(int parts) { return (parts + 7) / 8; }

double payload_bytes(const Message& message, const CostModel& costs) {
  switch (message.kind) {
    case MessageKind::kCandidate:
      return costs.shooter_record_bytes + double(message.loads.size()) * costs.load_record_bytes;
    case MessageKind::kShooter:
    case MessageKind::kStop:
      return costs.shooter_record_bytes +
             double(message.transfers.size()) * costs.transfer_order_bytes;
    case MessageKind::kPoints:
      return double(message.points.size()) * costs.point_bytes;
    case MessageKind::kAnswers:
      return double(message.masks.size()) * part_mask_bytes(message.mask_parts);
    case MessageKind::kPatches: {
      if (message.patch_records.size() != message.patches.size())
        throw std::logic_error("payload_bytes: a patch message without each patch's records");
      double bytes = 0.0;
      for (long records : message.patch_records)
        bytes += patch_record_bytes(records, message.patch_geometry, costs);
      return bytes;
    }
    case MessageKind::kIncrements:
      return double(message.increments.size()) * costs.radiosity_increment_bytes;
    case MessageKind::kElements: {
      double bytes = 0.0;
      for (const ElementShare& share : message.shares) bytes += render_record_bytes(*share, costs);
      return bytes;
    }
    case MessageKind::kCredit:
      return 0.0;
    case MessageKind::kHistogram:
      return costs.exposure_histogram_bytes;
    case MessageKind::kSelection:
      return costs.exposure_selection_bytes;
    case MessageKind::kPixels:
      return double(message.pixels.pixels.size()) * costs.pixel_bytes;
  }
  throw std::logic_error("payload_bytes: unknown message kind");
}

}  // namespace ncube
