# Two panels of one sheet locked edge to edge by a flat sliding dovetail.
# The lower panel's three tails slide into the upper panel's sockets.
import "std/joints.aidl"

thickness 3 mm

assembly board {
    solid lower {
        body = Rectangle(center=(0, 0), width=90, height=50)  # up to the tips: y 25
        tails = dovetail(part="tail", length=90 mm, depth=10 mm, tails=3, cy=15 mm)
    }
    solid upper {
        body = Rectangle(center=(0, 50), width=90, height=40)  # from the line: y 30
        sockets = dovetail(part="socket", length=90 mm, depth=10 mm, tails=3, cy=30 mm)
    }
    # assembled in the sheet's plane: the upper panel slid down onto the tails
    Place(upper, position=(0, -15, 0))
}
