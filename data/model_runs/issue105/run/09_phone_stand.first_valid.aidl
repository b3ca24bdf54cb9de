# Phone stand: two leaning side supports 110 mm tall joined by an 80 mm wide foot
# (3 mm plywood), leaning back at 65 degrees with a 10 mm lip in front; a 12 mm x
# 25 mm rounded charging-cable slot through the foot, centred on it.
import "std/stands.aidl"

thickness 3 mm

assembly phone_stand {
    stand = tablet_stand(width=80 mm, height=110 mm, angle=65 deg, lip=10 mm, thickness=3 mm)

    hole cable {
        s = Slot(center=(0, 0), length=25, width=12)
    }
    CenterInside(cable, stand.foot)
    CutInto(cable, stand.foot)
}
