// Display composite of a 2D solution.
#include "luxel/gi2d/display.h"

namespace luxel::gi2d {

Image displayImage(const Medium2D& medium, const Image& fluence, const ToneMapSettings& tone) {
    LUXEL_CHECK_EQ(fluence.width(), medium.width());
    LUXEL_CHECK_EQ(fluence.height(), medium.height());
    Image hdr(medium.width(), medium.height(), 3);
    for (int y = 0; y < hdr.height(); ++y) {
        for (int x = 0; x < hdr.width(); ++x) {
            hdr.setRgb(x, y, medium.emission.rgb(x, y) + fluence.rgb(x, y));
        }
    }
    return toneMap(hdr, tone);
}

}  // namespace luxel::gi2d
