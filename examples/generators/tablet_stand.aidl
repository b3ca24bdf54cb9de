# A tablet stand: two leaning supports with a lip, crossed by a foot.
import "std/stands.aidl"

thickness 3 mm

assembly stand {
    s = tablet_stand(width=140 mm, height=130 mm, angle=70 deg, lip=12 mm, thickness=3 mm)
}
