// The start-up floor of any topocut binary: a program that links OpenCV's core and imgproc (which
// every module's cv::Mat needs) and does nothing. startup_benchmark runs it beside topocut, so
// what topocut's own start-up adds can be told from what OpenCV's libraries cost.
#include <opencv2/core.hpp>
#include <opencv2/imgproc.hpp>

int main(int argc, char**) {
  // Never true when run by the benchmark; keeps both libraries linked (--as-needed drops unused ones).
  if (argc > 1000) {
    cv::Mat m(2, 2, CV_8U, cv::Scalar(0));
    cv::dilate(m, m, cv::Mat());
  }
  return 0;
}
