// The PNG sequence sink and the ffmpeg video sink, end to end on small frames.

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <sstream>

#include <stb/stb_image.h>

#include "output/png_sequence_sink.hpp"
#include "output/sha256.hpp"
#include "output/video_sink.hpp"
#include "support/temp_folder.hpp"

namespace sl {
namespace {

Image gradient(int w, int h, int frame) {
  Image image{w, h, std::vector<std::uint8_t>(std::size_t(w) * h * 3)};
  for (std::size_t i = 0; i < image.rgb.size(); ++i) image.rgb[i] = std::uint8_t(i * 7 + frame * 13);
  return image;
}

std::string run(const std::string& command) {
  std::string output;
  FILE* pipe = ::popen(command.c_str(), "r");
  char buffer[256];
  while (pipe && std::fgets(buffer, sizeof buffer, pipe)) output += buffer;
  if (pipe) ::pclose(pipe);
  return output;
}

TEST(PngSequenceSink, WritesFramesAndRecordsTheirChecksums) {
  const testing::TempFolder temp;
  const std::string folder = temp.path();
  FrameManifest manifest(folder, {{"test", "png"}});
  {
    PngSequenceSink sink(folder, manifest, 2);
    for (int k = 3; k < 9; ++k) sink.consume(k, gradient(32, 24, k));
    sink.finish();
  }
  EXPECT_EQ(frameFileName(3), "frame_00003.png");
  for (int k = 3; k < 9; ++k) {
    const auto entry = manifest.entry(k);
    ASSERT_TRUE(entry) << k;
    EXPECT_EQ(entry->file, frameFileName(k));
    EXPECT_TRUE(entry->pixelSha256.empty()) << "one hash per PNG frame: its file's";
    EXPECT_EQ(entry->fileSha256, sha256OfFile(folder + "/" + entry->file));
    int w = 0, h = 0, channels = 0;
    stbi_uc* pixels = stbi_load((folder + "/" + entry->file).c_str(), &w, &h, &channels, 3);
    ASSERT_TRUE(pixels) << entry->file;
    const Image expected = gradient(32, 24, k);
    EXPECT_TRUE(w == 32 && h == 24 && std::equal(expected.rgb.begin(), expected.rgb.end(), pixels)) << entry->file;
    stbi_image_free(pixels);
    EXPECT_TRUE(manifest.isFrameComplete(k));
  }
  EXPECT_FALSE(manifest.entry(2));
}

// A sink gives each frame's buffer back once its file is written (the render loop draws the next frames into
// them), and what it wrote is the frame it was given, not what the buffer holds later.
TEST(PngSequenceSink, GivesBuffersBackAfterWritingThem) {
  const testing::TempFolder temp;
  const std::string folder = temp.path();
  FrameManifest manifest(folder, {{"test", "png"}});
  ImageRecycler buffers;
  {
    PngSequenceSink sink(folder, manifest, 2);
    sink.recycleInto(buffers);
    for (int k = 0; k < 4; ++k) sink.consume(k, gradient(32, 24, k));
    sink.finish();
  }
  int givenBack = 0;
  for (Image image = buffers.take(); !image.rgb.empty(); image = buffers.take()) {
    EXPECT_EQ(image.rgb.size(), 32u * 24u * 3u);
    ++givenBack;
  }
  EXPECT_EQ(givenBack, 4);
  for (int k = 0; k < 4; ++k) {
    int w = 0, h = 0, channels = 0;
    stbi_uc* pixels = stbi_load((folder + "/" + frameFileName(k)).c_str(), &w, &h, &channels, 3);
    ASSERT_TRUE(pixels) << k;
    const Image expected = gradient(32, 24, k);
    EXPECT_TRUE(std::equal(expected.rgb.begin(), expected.rgb.end(), pixels)) << k;
    stbi_image_free(pixels);
  }
}

TEST(VideoSink, ProducesAPlayableMp4WithEveryFrame) {
  const testing::TempFolder temp;
  const std::string folder = temp.path();
  const std::string path = folder + "/clip.mp4";
  FrameManifest manifest(folder, {{"test", "video"}}, "clip.mp4.manifest.json");
  {
    VideoSink sink({path, VideoFormat::Mp4, VideoQuality::High, 64, 48, 30}, manifest);
    for (int k = 0; k < 12; ++k) sink.consume(k, gradient(64, 48, k));
    sink.finish();
  }
  const std::string frames =
      run("ffprobe -v error -count_frames -select_streams v:0 -show_entries stream=nb_read_frames,codec_name,pix_fmt "
          "-of csv=p=0 '" +
          path + "'");
  EXPECT_EQ(frames, "h264,yuv420p,12\n");
  EXPECT_EQ(manifest.entry(11)->pixelSha256, sha256Hex(gradient(64, 48, 11).rgb));
  EXPECT_TRUE(manifest.entry(11)->file.empty());
}

// Every format the extension can ask for: the codec ffprobe sees, every frame, the same bytes twice, and odd
// sizes allowed where the format has no chroma subsampling (GIF).
TEST(VideoSink, WebmAndGifByExtensionWithEveryFrameDeterministically) {
  const testing::TempFolder temp;
  const std::string folder = temp.path();
  struct Case {
    VideoFormat format;
    int width, height;
    std::string probe;
  };
  for (const Case& c : {Case{VideoFormat::Webm, 64, 48, "vp9,yuv420p,12\n"}, Case{VideoFormat::Gif, 63, 47, "gif,bgra,12\n"}}) {
    const std::string extension(traits(c.format).name);
    SCOPED_TRACE(extension);
    std::string first;
    for (int take = 0; take < 2; ++take) {
      const std::string path = folder + "/clip." + extension;
      FrameManifest manifest(folder, {{"test", extension}}, "clip." + extension + ".manifest.json",
                             FrameManifest::Existing::replace);
      {
        VideoSink sink({path, c.format, VideoQuality::Medium, c.width, c.height, 30}, manifest);
        for (int k = 0; k < 12; ++k) sink.consume(k, gradient(c.width, c.height, k));
        sink.finish();
      }
      EXPECT_EQ(run("ffprobe -v error -count_frames -select_streams v:0 -show_entries "
                    "stream=codec_name,pix_fmt,nb_read_frames -of csv=p=0 '" + path + "'"),
                c.probe);
      const std::string bytes = sha256OfFile(path);
      if (take == 0) first = bytes;
      else EXPECT_EQ(bytes, first) << "the same frames gave different bytes";
    }
  }
  EXPECT_THROW(VideoSink({folder + "/odd.webm", VideoFormat::Webm, VideoQuality::High, 63, 47, 30},
                         *std::make_unique<FrameManifest>(folder, nlohmann::json{{"t", 1}}, "x.json",
                                                         FrameManifest::Existing::replace)),
               std::invalid_argument);
}

// output.hold_start and output.hold_end: the first and the last frame shown longer (cloned by the encoder), every
// frame still checked by ffprobe; in the lossless GIF the held frames decode to exactly the first and the last.
TEST(VideoSink, HoldsTheFirstAndTheLastFrame) {
  const testing::TempFolder temp;
  const std::string folder = temp.path();
  for (const VideoFormat format : {VideoFormat::Mp4, VideoFormat::Gif}) {
    const std::string extension(traits(format).name);
    SCOPED_TRACE(extension);
    const std::string path = folder + "/held." + extension;
    FrameManifest manifest(folder, {{"test", extension}}, "held." + extension + ".manifest.json");
    {
      VideoSettings settings{path, format, VideoQuality::High, 64, 48, 30};
      settings.holdStartFrames = 5;
      settings.holdEndFrames = 7;
      VideoSink sink(settings, manifest);
      for (int k = 0; k < 12; ++k) sink.consume(k, gradient(64, 48, k));
      sink.finish();
    }
    EXPECT_EQ(
        run("ffprobe -v error -count_frames -select_streams v:0 -show_entries stream=nb_read_frames -of csv=p=0 '" +
            path + "'"),
        "24\n");
    EXPECT_EQ(manifest.entry(11)->pixelSha256, sha256Hex(gradient(64, 48, 11).rgb));  // the frames, not the holds
    if (format != VideoFormat::Gif) continue;
    std::istringstream lines(run("ffmpeg -v error -i '" + path + "' -f framemd5 -"));
    std::vector<std::string> hashes;
    for (std::string line; std::getline(lines, line);)
      if (!line.empty() && line[0] != '#') hashes.push_back(line.substr(line.rfind(',') + 1));
    ASSERT_EQ(hashes.size(), 24u);
    for (int k = 1; k <= 5; ++k) EXPECT_EQ(hashes[std::size_t(k)], hashes[0]) << k;
    for (int k = 16; k < 23; ++k) EXPECT_EQ(hashes[std::size_t(k)], hashes[23]) << k;
    EXPECT_NE(hashes[6], hashes[0]);
  }
}

// output.video_crf: the constant rate factor ffmpeg is given for mp4 and webm instead of the quality's; a GIF has
// none.
TEST(VideoSink, AConstantRateFactorReplacesTheQualitysOwn) {
  const auto crfOf = [](const VideoSettings& s) {
    const std::vector<std::string> args = ffmpegArguments(s, "x");
    const auto at = std::find(args.begin(), args.end(), "-crf");
    return at == args.end() ? std::string("none") : *(at + 1);
  };
  VideoSettings s{"x.mp4", VideoFormat::Mp4, VideoQuality::Medium, 64, 48, 30};
  EXPECT_EQ(crfOf(s), "23");
  s.crf = 35;
  EXPECT_EQ(crfOf(s), "35");
  s.format = VideoFormat::Webm;
  EXPECT_EQ(crfOf(s), "35");
  s.crf = -1;
  EXPECT_EQ(crfOf(s), "36");
  s.format = VideoFormat::Gif;
  s.crf = 10;
  EXPECT_EQ(crfOf(s), "none");
}

std::vector<std::string> folderNames(const std::string& folder) {
  std::vector<std::string> names;
  for (const auto& entry : std::filesystem::directory_iterator(folder)) names.push_back(entry.path().filename());
  std::sort(names.begin(), names.end());
  return names;
}

// An unfinished video (interrupted, failed) never takes the final name, leaves no temporary, and is not listed.
TEST(VideoSink, AnUnfinishedVideoLeavesTheEarlierOneUntouched) {
  const testing::TempFolder temp;
  const std::string folder = temp.path();
  const std::string path = folder + "/clip.mp4";
  {
    FrameManifest manifest(folder, {{"test", "first"}}, "clip.mp4.manifest.json", FrameManifest::Existing::replace);
    VideoSink sink({path, VideoFormat::Mp4, VideoQuality::High, 64, 48, 30}, manifest);
    for (int k = 0; k < 3; ++k) sink.consume(k, gradient(64, 48, k));
    sink.finish();
  }
  const std::string firstVideo = sha256OfFile(path), firstManifest = sha256OfFile(path + ".manifest.json");
  {
    FrameManifest manifest(folder, {{"test", "second"}}, "clip.mp4.manifest.json", FrameManifest::Existing::replace);
    VideoSink sink({path, VideoFormat::Mp4, VideoQuality::High, 64, 48, 30}, manifest);
    for (int k = 0; k < 5; ++k) sink.consume(k, gradient(64, 48, k + 1));
  }  // destroyed without finish()
  EXPECT_EQ(sha256OfFile(path), firstVideo);
  EXPECT_EQ(sha256OfFile(path + ".manifest.json"), firstManifest);
  // The claim file of one render at a time stays, as in a PNG folder; no temporary does.
  const std::vector<std::string> expected = {".clip.mp4.manifest.json.active", "clip.mp4", "clip.mp4.manifest.json"};
  EXPECT_EQ(folderNames(folder), expected);
}

bool stopAtOnce() { return true; }

// Class 11 of the fourth hostile round: two renders finishing the same video interleaved their renames and
// manifests (one render's video beside the other's manifest, both exit 0). One render writes a video at a time
// now: a second waits for the first's manifest to be written (cancellable, bounded by its lock wait), and then
// replaces both.
TEST(VideoSink, OneRenderAtATimeWritesAVideoAndItsManifest) {
  const testing::TempFolder temp;
  const std::string folder = temp.path();
  const std::string path = folder + "/clip.mp4";
  {
    FrameManifest first(folder, {{"test", "first"}}, "clip.mp4.manifest.json", FrameManifest::Existing::replace);
    EXPECT_THROW(FrameManifest(folder, {{"test", "second"}}, "clip.mp4.manifest.json",
                               FrameManifest::Existing::replace, FrameManifest::Claim::join, stopAtOnce),
                 LockWaitCancelled);
    try {
      FrameManifest(folder, {{"test", "second"}}, "clip.mp4.manifest.json", FrameManifest::Existing::replace,
                    FrameManifest::Claim::join, nullptr, 0.0);
      ADD_FAILURE() << "a second render claimed a video another is writing";
    } catch (const std::runtime_error& error) {
      EXPECT_NE(std::string(error.what()).find("waiting for " + folder + "/.clip.mp4.manifest.json.active"),
                std::string::npos)
          << error.what();
    }
    VideoSink sink({path, VideoFormat::Mp4, VideoQuality::High, 64, 48, 30}, first);
    for (int k = 0; k < 3; ++k) sink.consume(k, gradient(64, 48, k));
    sink.finish();
  }
  // The first render is done (its manifest written, its claim released): the next one may take the video over.
  FrameManifest second(folder, {{"test", "second"}}, "clip.mp4.manifest.json", FrameManifest::Existing::replace,
                       FrameManifest::Claim::join, nullptr, 0.0);
  EXPECT_EQ(readManifestFile(path + ".manifest.json").frames.size(), 3u);
}

// A finished video replaces an earlier one and its manifest, even one written for another render.
TEST(VideoSink, AFinishedVideoReplacesTheEarlierOneAndItsManifest) {
  const testing::TempFolder temp;
  const std::string folder = temp.path();
  const std::string path = folder + "/take:2.mp4";  // a colon: ffmpeg must not read "take" as a protocol
  for (const int frames : {4, 2}) {
    FrameManifest manifest(folder, {{"frames", frames}}, "take:2.mp4.manifest.json", FrameManifest::Existing::replace);
    VideoSink sink({path, VideoFormat::Mp4, VideoQuality::High, 64, 48, 30}, manifest);
    for (int k = 0; k < frames; ++k) sink.consume(k, gradient(64, 48, k));
    sink.finish();
  }
  EXPECT_EQ(
      run("ffprobe -v error -count_frames -select_streams v:0 -show_entries stream=nb_read_frames -of csv=p=0 'file:" +
          path + "'"),
      "2\n");
  FrameManifest reread(folder, {{"frames", 2}}, "take:2.mp4.manifest.json");  // merge mode: throws for another render
  EXPECT_TRUE(reread.entry(1));
  EXPECT_FALSE(reread.entry(2)) << "the earlier render's frames must not survive in the manifest";
}

TEST(VideoSink, RejectsOddSizesAndMissingFfmpeg) {
  const testing::TempFolder temp;
  const std::string folder = temp.path();
  FrameManifest manifest(folder, {{"test", "video"}}, "v.manifest.json");
  EXPECT_THROW(VideoSink({folder + "/a.mp4", VideoFormat::Mp4, VideoQuality::High, 63, 48, 30}, manifest), std::invalid_argument);
  VideoSettings missing{folder + "/b.mp4", VideoFormat::Mp4, VideoQuality::High, 64, 48, 30};
  missing.ffmpeg = "/nonexistent/ffmpeg";
  EXPECT_THROW(VideoSink(missing, manifest), std::runtime_error);
}

TEST(VideoSink, FfmpegFailureIsReported) {
  const testing::TempFolder temp;
  const std::string folder = temp.path();
  FrameManifest manifest(folder, {{"test", "video"}}, "v.manifest.json");
  VideoSink sink({folder + "/no/such/dir/c.mp4", VideoFormat::Mp4, VideoQuality::High, 64, 48, 30}, manifest);  // ffmpeg cannot open the output
  EXPECT_THROW(
      {
        for (int k = 0; k < 50; ++k) sink.consume(k, gradient(64, 48, k));
        sink.finish();
      },
      std::runtime_error);
}

}  // namespace
}  // namespace sl
