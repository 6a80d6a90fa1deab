#pragma once
// Where and how frames are written: the scene's "output" section.

#include <string>

#include "contracts/image.hpp"

namespace sl {

struct OutputSettings {
  int fps = 30;
  ImageSize size;      // the frame size, for the renderer and every sink
  std::string folder;  // default renders/<name>, relative to the working directory
  bool png = true;     // write PNG frames
  std::string video;   // an mp4 path, empty = no video
};

}  // namespace sl
