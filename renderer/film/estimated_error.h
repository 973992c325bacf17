#pragma once
// How far a film's image probably is from the converged image, judged from its own per-pixel variance: the
// stopping rule of isotrace render --reference --target-error (docs/reference-images.md).
#include "renderer/film/film.h"

namespace isotrace {

// sqrt of the mean, over every pixel and radiance channel, of Var[mean] / (|mean| + 0.01)^2: the expected value
// of pbrt's relative MSE between this image and the converged one (the 0.01 is pbrt's, kRelativeMseEpsilon), as
// a root so that 0.01 reads as "about 1 % noise". Infinite while any pixel has fewer than two samples.
double estimated_relative_error(const Film& film);

}  // namespace isotrace
