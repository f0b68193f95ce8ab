// The modeled size of each message kind (nodes/messages.h), against bytes worked out by hand
// from the record sizes of platforms/cost_model.json.
#include "nodes/messages.h"

#include <stdexcept>

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
  // Sections 4.1, 4.2: a candidate carrying 3 loads of 6 ints: 88 + 3 x 24 = 160; a shooter
  // carrying 2 balancing orders of 4 ints: 88 + 2 x 16 = 120.
  Message candidate = of(MessageKind::kCandidate);
  candidate.loads.resize(3);
  EXPECT_EQ(payload_bytes(candidate, c), 160);
  Message shooter = of(MessageKind::kShooter);
  shooter.transfers.resize(2);
  EXPECT_EQ(payload_bytes(shooter, c), 120);
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
  // Load balancing (4.2): two patches of 6 and 10 element records, each with its radiosity
  // data (48) and 184 bytes per record: 48 + 6 x 184 + 48 + 10 x 184 = 3040; with their
  // geometry (68 each, V > 0) 3176.
  Message patches = of(MessageKind::kPatches);
  patches.patches.resize(2);
  patches.patch_records = {6, 10};
  EXPECT_EQ(payload_bytes(patches, c), 3040);
  patches.patch_geometry = true;
  EXPECT_EQ(payload_bytes(patches, c), 3176);
  patches.patch_records.pop_back();
  EXPECT_THROW(payload_bytes(patches, c), std::logic_error);
  // Two shares of 3 and 4 render records of 104 bytes: 7 x 104 = 728; one of the records
  // with 2 T-vertices on its boundary (4 corners and 2 more points) adds 2 x 24: 776.
  RenderElement quad;
  quad.boundary.resize(4);
  std::vector<RenderElement> with_t_vertices(4, quad);
  Message elements = of(MessageKind::kElements);
  elements.shares = {std::make_shared<const std::vector<RenderElement>>(3, quad),
                     std::make_shared<const std::vector<RenderElement>>(with_t_vertices)};
  EXPECT_EQ(payload_bytes(elements, c), 728);
  with_t_vertices[1].boundary.resize(6);
  elements.shares[1] = std::make_shared<const std::vector<RenderElement>>(with_t_vertices);
  EXPECT_EQ(payload_bytes(elements, c), 776);
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
