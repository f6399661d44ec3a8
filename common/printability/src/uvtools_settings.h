#pragma once
// UVtools' default settings of its printability checks (IssueManager, LayerIssueConfiguration),
// as the checks (check_layers.h) use them.
#include <cstdint>

namespace slicereuse {

constexpr uint8_t kIslandLit = 2;  // Island BinaryThreshold 1 (pixels <= 1 are black)
constexpr uint8_t kIslandPointLevel = 10;  // Island RequiredPixelBrightnessToProcessCheck
constexpr uint8_t kSupportLevel = 150;  // Island RequiredPixelBrightnessToSupport
constexpr double kSupportMultiplier = 0.25;  // Island RequiredPixelsToSupportMultiplier
constexpr uint64_t kPixelsToSupport = 10;  // Island RequiredPixelsToSupport (enhanced detection)
constexpr uint64_t kIslandMinArea = 1;  // Island RequiredAreaToProcessCheck
constexpr uint64_t kOverhangMinPixels = 1;  // Overhang RequiredPixelsToConsider
constexpr int kErodeIterations = 40;  // Overhang ErodeIterations
constexpr int kDifferenceThreshold = 127;  // Overhang: the layer minus the one below, thresholded at 127
constexpr uint8_t kTrapSolid = 101;  // ResinTrap BinaryThreshold 100 (pixels <= 100 are air)
constexpr uint64_t kRequiredAreaToProcessCheck = 4;  // ResinTrap RequiredAreaToProcessCheck
constexpr uint64_t kRequiredBlackPixelsToDrain = 10;  // ResinTrap RequiredBlackPixelsToDrain
constexpr uint64_t kCupMinArea = 100;  // ResinTrap RequiredAreaToConsiderSuctionCup
constexpr double kCupMinHeightMm = 0.5;  // ResinTrap RequiredHeightToConsiderSuctionCup
constexpr uint8_t kTouchLevel = 127;  // TouchingBound MinimumPixelBrightness
constexpr int kTouchMargin = 5;  // TouchingBound MarginLeft/Top/Right/Bottom

}  // namespace slicereuse
