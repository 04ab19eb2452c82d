// png_check.cpp - checks a demo screenshot for the smoke test: expected
// size, not blank, and enough pixels of the path colours and of the
// character's skin colour (head and hands of the body; joints and head of
// the skeleton view), so a picture that lost the path or the character
// fails. Prints what it counted.
//
// usage: smg-demo-pngcheck FILE --size W H [--path MIN] [--character MIN]
//                          [--colour R G B MIN]... [--dark x0 y0 x1 y1 MAXMEAN]
//                          [--inside x0 y0 x1 y1 MIN]
// --colour counts pixels within 12 (sum of channel differences) of R G B.
// --inside: the character's skin pixels (head, hands) lie in the box
// x0 y0 x1 y1 (the projected skeleton the demo prints) grown by a quarter
// of its height on every side: at least MIN there, and at most 5 % of all
// skin pixels outside (a body drawn elsewhere or exploded vertices fail).
#include <stb_image.h>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <set>
#include <string>
#include <vector>

namespace {

// The flat (unlit) path colours of demo/palette.cpp: walk blue, run red.
const int kPathColours[][3] = {{41, 107, 230}, {224, 41, 36}};

bool near(const unsigned char* p, const int* c) {
  return std::abs(p[0] - c[0]) + std::abs(p[1] - c[1]) + std::abs(p[2] - c[2]) <= 12;
}

bool is_path(const unsigned char* p) {
  for (const auto& c : kPathColours)
    if (near(p, c)) return true;
  return false;
}

struct ColourRule {
  int rgb[3];
  long min = 0, count = 0;
};

// kSkinColour (0.93, 0.80, 0.62) under any white-light intensity keeps its
// channel ratios; nothing else in the scene has them.
bool is_skin(const unsigned char* p) {
  if (p[0] < 60) return false;
  double g = double(p[1]) / p[0], b = double(p[2]) / p[0];
  return g > 0.78 && g < 0.94 && b > 0.55 && b < 0.78;
}

int fail(const char* msg) {
  std::fprintf(stderr, "png-check: FAIL: %s\n", msg);
  return 1;
}

}  // namespace

int main(int argc, char** argv) {
  if (argc < 2) {
    std::fprintf(stderr, "usage: %s FILE --size W H [--path MIN] [--character MIN] [--dark x0 y0 x1 y1 MAX] "
                 "[--inside x0 y0 x1 y1 MIN]\n",
                 argv[0]);
    return 2;
  }
  int want_w = -1, want_h = -1, min_path = -1, min_char = -1;
  int dark[5] = {-1, 0, 0, 0, 0};
  int inside[5] = {-1, 0, 0, 0, 0};
  std::vector<ColourRule> rules;
  for (int i = 2; i < argc; ++i) {
    std::string a = argv[i];
    if (a == "--size" && i + 2 < argc) {
      want_w = std::atoi(argv[++i]);
      want_h = std::atoi(argv[++i]);
    } else if (a == "--path" && i + 1 < argc) {
      min_path = std::atoi(argv[++i]);
    } else if (a == "--character" && i + 1 < argc) {
      min_char = std::atoi(argv[++i]);
    } else if (a == "--colour" && i + 4 < argc) {
      ColourRule r;
      for (int k = 0; k < 3; ++k) r.rgb[k] = std::atoi(argv[++i]);
      r.min = std::atol(argv[++i]);
      rules.push_back(r);
    } else if (a == "--inside" && i + 5 < argc) {
      for (int k = 0; k < 5; ++k) inside[k] = std::atoi(argv[++i]);
    } else if (a == "--dark" && i + 5 < argc) {
      for (int k = 0; k < 5; ++k) dark[k] = std::atoi(argv[++i]);
    } else {
      std::fprintf(stderr, "png-check: bad argument '%s'\n", argv[i]);
      return 2;
    }
  }
  int w = 0, h = 0, n = 0;
  unsigned char* px = stbi_load(argv[1], &w, &h, &n, 3);
  if (!px) return fail((std::string("cannot read PNG ") + argv[1]).c_str());
  int status = 0;
  std::printf("png-check: %s %dx%d", argv[1], w, h);
  if (want_w >= 0 && (w != want_w || h != want_h)) {
    std::printf("\n");
    std::fprintf(stderr, "png-check: FAIL: expected %dx%d\n", want_w, want_h);
    stbi_image_free(px);
    return 1;
  }
  long path = 0, skin = 0, skin_in = 0;
  int margin = (inside[3] - inside[1]) / 4;
  double sum[3] = {0, 0, 0}, sum2[3] = {0, 0, 0};
  std::set<unsigned> colours;
  for (long i = 0; i < long(w) * h; ++i) {
    const unsigned char* p = px + i * 3;
    path += is_path(p);
    skin += is_skin(p);
    int x = int(i % w), y = int(i / w);
    skin_in += inside[0] >= 0 && is_skin(p) && x >= inside[0] - margin && x <= inside[2] + margin &&
               y >= inside[1] - margin && y <= inside[3] + margin;
    for (ColourRule& r : rules) r.count += near(p, r.rgb);
    for (int c = 0; c < 3; ++c) {
      sum[c] += p[c];
      sum2[c] += double(p[c]) * p[c];
    }
    if (colours.size() < 100000) colours.insert(unsigned(p[0]) << 16 | unsigned(p[1]) << 8 | p[2]);
  }
  double npx = double(w) * h, spread = 0;
  for (int c = 0; c < 3; ++c) spread = std::fmax(spread, std::sqrt(sum2[c] / npx - (sum[c] / npx) * (sum[c] / npx)));
  std::printf(" colours=%zu stddev=%.1f path_px=%ld skin_px=%ld", colours.size(), spread, path, skin);
  if (dark[0] >= 0) {
    double m = 0;
    long k = 0;
    for (int y = dark[1]; y < dark[3] && y < h; ++y)
      for (int x = dark[0]; x < dark[2] && x < w; ++x, ++k) {
        const unsigned char* p = px + (long(y) * w + x) * 3;
        m += (p[0] + p[1] + p[2]) / 3.0;
      }
    m = k ? m / double(k) : 255.0;
    std::printf(" dark_mean=%.1f", m);
    if (m > dark[4]) status = fail("the HUD region is not dark (ImGui panel missing?)");
  }
  if (inside[0] >= 0) std::printf(" skin_in_box=%ld", skin_in);
  for (const ColourRule& r : rules) std::printf(" rgb(%d,%d,%d)=%ld", r.rgb[0], r.rgb[1], r.rgb[2], r.count);
  std::printf("\n");
  for (const ColourRule& r : rules)
    if (r.count < r.min) status = fail("too few pixels of a required colour");
  if (colours.size() < 50 || spread < 5.0) status = fail("picture is blank");
  if (min_path >= 0 && path < min_path) status = fail("too few path pixels: the path is not visible");
  if (inside[0] >= 0 && skin_in < inside[4]) status = fail("too few character pixels inside the skeleton's box");
  if (inside[0] >= 0 && double(skin - skin_in) > 0.05 * double(skin))
    status = fail("character pixels outside the skeleton's box (body drawn elsewhere?)");
  if (min_char >= 0 && skin < min_char) status = fail("too few character pixels: the character is not visible");
  stbi_image_free(px);
  return status;
}
