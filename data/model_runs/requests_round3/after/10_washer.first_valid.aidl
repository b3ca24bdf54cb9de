# A flat washer: outer diameter 32.456 mm, inner diameter 17.272 mm, 1.524 mm thick.
import "std/shapes.aidl"

thickness 1.524 mm

solid part {
    w = washer(outer=32.456 mm, inner=17.272 mm)
}
