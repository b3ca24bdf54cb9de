# A laptop stand: two sloping sides joined by two cross bars.
import "std/stands.aidl"

thickness 3 mm

assembly stand {
    s = laptop_stand(width=260 mm, depth=220 mm, height=30 mm, angle=15 deg, thickness=3 mm)
}
