#pragma once

// Every tolerance of the render tests, with the reason for its value (docs/golden-images.md).
//
// Pixel convention, shared by Camera::project and OpenGL: pixel (i, j), i to the right and j down from
// the top-left corner, covers [i, i + 1) x [j, j + 1) and is sampled at its centre (i + 0.5, j + 0.5)
// (OpenGL's fragment centres; OsmesaContext::read flips OpenGL's bottom-up rows into top-down ones).
namespace dropscope::test {

// A sphere or ellipsoid impostor decides coverage per fragment at the pixel centre, by intersecting the
// eye ray with the unit sphere in float. So a pixel whose centre is farther than this from the true
// silhouette (inside or out) must be covered or background, and only pixels within it may go either
// way: float rounding (24-bit mantissa) of the anchor-relative positions, the transforms and the
// discriminant moves the decided edge by a tiny fraction of a pixel, while a wrong field of view, aspect
// ratio, radius or rotation moves it by several pixels.
inline constexpr double kSilhouetteBandPixels = 1.0;

// Of the pixels within kSilhouetteBandPixels of the silhouette, the share that may still be decided the
// other way than the exact test at their centre: those whose centre lies within float rounding of the
// silhouette, a few thousandths of a pixel at most, so about one pixel in a few hundred band pixels would
// be expected; in practice the renderer and the engine agree on every pixel of these tests. A rotation
// off by a few degrees, or a radius off by a pixel, flips tens of band pixels.
inline constexpr double kBandMismatchShare = 0.01;

// The radius of a circle with the area of the covered pixels, against the projected radius. The count
// of pixel centres inside a circle of radius R differs from pi R^2 by about R^(2/3) (the Gauss circle
// problem), i.e. by < 0.05 px of radius for R ~ 30 px; float rounding adds nothing visible.
inline constexpr double kAreaRadiusPixels = 0.5;

// How far (Chebyshev distance, in pixels) the lit pixel of a 1-pixel line may be from the pixel that
// holds a projected point of it. OpenGL's diamond-exit rule lights, for an x-major line, the one pixel
// per column whose centre is within half a pixel of the line in y (y-major alike), so the lit pixel is
// the point's own pixel or its neighbour across the minor axis; the last pixel of a segment is left
// unlit (half-open), so a box corner is found in the next pixel along one of its three edges.
inline constexpr int kLineReachPixels = 1;

// Every lit line pixel's centre lies within this distance of some projected segment. The diamond-exit
// rule gives half a pixel; rasterisers that draw a 1-pixel line as a thin quad give the same. Doubled,
// for the float rounding of the vertex positions and in case the driver widens a line's ends.
inline constexpr double kLineDistancePixels = 1.0;

// Sample points along a projected segment stay this share of its length away from its two ends, where
// the half-open rule and the joins with other segments decide which pixel is lit.
inline constexpr double kSegmentEndShare = 0.05;

// Golden images (docs/golden-images.md). On the machine that made them a snapshot is reproduced bit for
// bit (Snapshot.SameArgumentsGiveIdenticalPixels); the thresholds are for another build or machine.
//
// A pixel differs when any channel (R, G, B, A, of 255) differs by more than this. Another llvmpipe
// build or CPU (its SSE / AVX code paths, its LLVM) may round the shading (normalize, dot, the headlight
// term) a level or two differently; 8 is several times that, and far below a deliberate change: palette
// colours differ by 40 levels and more, and shading or opacity changes move whole shapes by more.
inline constexpr int kGoldenChannelTolerance = 8;
// A golden case fails when more than this share of its pixels differ: 38 pixels of a 320x240 image.
// Allowed: the few pixels whose centre lies within float rounding of a silhouette or a line's diamond,
// which another rasteriser may decide the other way. Caught: a shape moved by one pixel (its whole
// outline, hundreds of pixels), a missing or extra line, a changed colour.
inline constexpr double kGoldenMaxDifferingShare = 0.0005;

// A frame drawn on the processor (RenderOptions::processorRaster) against OpenGL's of the same scene, every sphere at
// its exact depth in both: at most this share of the pixels differ by more than kGoldenChannelTolerance. The
// processor takes a line's pixels by OpenGL's rule but decides the first and last pixel by the centres' columns,
// not the diamonds: in ProcessorRaster.DrawsThePictureOpenGLDraws 76 of its 19,200 pixels differ, all single pixels
// at some of the 303 segments' 606 ends (0.40 %). 0.5 % leaves 20 pixels for another build's rounding and catches a
// segment drawn a row off along its length, or one across the near plane left unclipped (173 pixels), let alone a
// sphere moved or shaded otherwise (its whole outline or area).
inline constexpr double kProcessorMaxDifferingShare = 0.005;

}  // namespace dropscope::test
