// The modeled size of each message kind (nodes/messages.h), against bytes worked out by hand
// from the record sizes of platforms/cost_model.json.
#include "nodes/messages.h"

#include <gtest/gtest.h>

namespace ncube {
namespace {

std::string repo(const std::string& path) { return std::string(NCUBE_SOURCE_DIR) + "/" + path; }

Message of(MessageKind kind) {
  Message m;
  m.kind = kind;
  return m;
}

TEST(Messages, PartMasksTakeOneBitPerPartInWholeBytes) {
  EXPECT_EQ(part_mask_bytes(64), 8);
  EXPECT_EQ(part_mask_bytes(16), 2);
  EXPECT_EQ(part_mask_bytes(9), 2);
  EXPECT_EQ(part_mask_bytes(4), 1);
  EXPECT_EQ(part_mask_bytes(1), 1);
}

TEST(Messages, EachKindHasItsHandCountedSize) {
  const CostModel c = load_cost_model(repo("platforms/cost_model.json"));
  // The shooter record: patch index 4, 4 vertices 48, normal 12, plane offset 4, vertex
  // count 4, unshot RGB 12, unshot power 4 = 88 bytes; a stop takes the shooter's place.
  EXPECT_EQ(payload_bytes(of(MessageKind::kCandidate), c), 88);
  EXPECT_EQ(payload_bytes(of(MessageKind::kShooter), c), 88);
  EXPECT_EQ(payload_bytes(of(MessageKind::kStop), c), 88);
  // A block of 37 points of 3 floats and a patch index: 37 x 16 = 592 bytes.
  Message points = of(MessageKind::kPoints);
  points.points.resize(37);
  points.point_patches.resize(37);
  EXPECT_EQ(payload_bytes(points, c), 592);
  // Its answers: 37 masks of 64 parts (8 bytes) = 296; of 16 parts (2 bytes) = 74.
  Message answers = of(MessageKind::kAnswers);
  answers.masks.resize(37);
  answers.mask_parts = 64;
  EXPECT_EQ(payload_bytes(answers, c), 296);
  answers.mask_parts = 16;
  EXPECT_EQ(payload_bytes(answers, c), 74);
  // Two shares of 3 and 4 render records of 104 bytes: 7 x 104 = 728.
  Message elements = of(MessageKind::kElements);
  elements.shares = {std::make_shared<const std::vector<RenderElement>>(3),
                     std::make_shared<const std::vector<RenderElement>>(4)};
  EXPECT_EQ(payload_bytes(elements, c), 728);
  // A credit is its header only.
  EXPECT_EQ(payload_bytes(of(MessageKind::kCredit), c), 0);
  // Exposure: 2 x (256 x 4 + 8) = 2064 up, 2 x (8 + 4 + 8) = 40 down.
  EXPECT_EQ(payload_bytes(of(MessageKind::kHistogram), c), 2064);
  EXPECT_EQ(payload_bytes(of(MessageKind::kSelection), c), 40);
  // 5 x 2 finished pixels of 3 bytes: 30.
  Message pixels = of(MessageKind::kPixels);
  pixels.pixels = Image(5, 2);
  EXPECT_EQ(payload_bytes(pixels, c), 30);
}

}  // namespace
}  // namespace ncube
