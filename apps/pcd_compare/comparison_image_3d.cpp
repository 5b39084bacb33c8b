#include "comparison_image_3d.h"

#include <string>
#include <utility>

#include "common/plane_view.h"

namespace pcd_compare {

floodplane::io::RgbImage comparisonImage3d(const std::vector<Panel>& panels, const Cloud::ConstPtr& cloud,
                                           std::size_t min_points) {
  std::vector<std::pair<std::string, floodplane::io::RgbImage>> images;
  for (const Panel& panel : panels) {
    floodplane::view::PlaneScene scene;
    scene.cloud = cloud;
    scene.colour_labels = panel.colour_labels;
    const std::vector<std::uint32_t>& segments =
        panel.segment_labels.empty() ? panel.colour_labels : panel.segment_labels;
    scene.planes = floodplane::view::planeMarkersFromLabels(*cloud, segments, panel.colour_labels, min_points);
    scene.show_plane_text = false;  // segment numbers differ between methods and mean nothing here
    images.emplace_back(panel.title,
                        floodplane::view::renderImage(scene, floodplane::view::CameraView::oblique,
                                                      static_cast<int>(cloud->width), static_cast<int>(cloud->height)));
  }
  return titledImages(images);
}

}  // namespace pcd_compare
