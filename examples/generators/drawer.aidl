# A drawer in its carcass, sized by the space inside the carcass (outside=false).
import "std/boxes.aidl"
thickness 3 mm
kerf 0.15 mm

assembly desk_drawer {
    unit = drawer(length=150 mm, depth=120 mm, height=60 mm, thickness=3 mm, outside=false)
}
