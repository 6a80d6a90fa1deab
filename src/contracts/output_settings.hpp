#pragma once
// Where and how frames are written: the scene's "output" section.

#include <string>

#include "contracts/image.hpp"
#include "contracts/registry.hpp"

namespace sl {

struct OutputSettings {
  int fps = 30;
  ImageSize size;      // the frame size, for the renderer and every sink
  std::string folder;  // default renders/<name>, relative to the working directory
  bool png = true;     // write PNG frames
  PngCompression pngCompression = PngCompression::Fast;
  std::string video;   // a .mp4, .webm or .gif path (the format by its extension), empty = no video
  VideoQuality videoQuality = VideoQuality::High;
  int videoCrf = -1;  // the encoder's constant rate factor (mp4, webm) instead of videoQuality's; -1: not given
  double holdStart = 0, holdEnd = 0;  // seconds a video shows its first and its last frame before and after playing
  // How many times as fast as the scene's time a video plays: every frame shown, at fps x playbackSpeed frames a
  // second (the PNG frames are the same at any speed).
  double playbackSpeed = 1;
  double videoFps() const { return double(fps) * playbackSpeed; }
};

}  // namespace sl
