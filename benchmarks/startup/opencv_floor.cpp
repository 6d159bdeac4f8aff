// The start-up floor of any topocut binary: a program that links OpenCV's core and imgproc (which
// every module's cv::Mat needs) and does nothing. startup_benchmark runs it beside topocut, so
// what topocut's own start-up adds can be told from what OpenCV's libraries cost. Built a second
// time without FLOOR_WITH_IMGPROC, it links core alone: the least any binary holding a cv::Mat pays.
#include <opencv2/core.hpp>
#ifdef FLOOR_WITH_IMGPROC
#include <opencv2/imgproc.hpp>
#endif

int main(int argc, char**) {
  // Never true when run by the benchmark; keeps the libraries linked (--as-needed drops unused ones).
  if (argc > 1000) {
    cv::Mat m(2, 2, CV_8U, cv::Scalar(0));
#ifdef FLOOR_WITH_IMGPROC
    cv::dilate(m, m, cv::Mat());
#endif
    return m.rows;
  }
  return 0;
}
