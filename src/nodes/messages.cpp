#include "nodes/messages.h"

#include <stdexcept>

namespace ncube {

double part_mask_bytes(int parts) { return (parts + 7) / 8; }

double payload_bytes(const Message& message, const CostModel& costs) {
  switch (message.kind) {
    case MessageKind::kCandidate:
    case MessageKind::kShooter:
    case MessageKind::kStop:
      return costs.shooter_record_bytes;
    case MessageKind::kPoints:
      return double(message.points.size()) * costs.point_bytes;
    case MessageKind::kAnswers:
      return double(message.masks.size()) * part_mask_bytes(message.mask_parts);
    case MessageKind::kElements: {
      double records = 0.0;
      for (const ElementShare& share : message.shares) records += double(share->size());
      return records * costs.render_element_bytes;
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
