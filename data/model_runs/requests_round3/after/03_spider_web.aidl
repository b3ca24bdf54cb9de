# A spider-web wall decoration: a ring frame 120 mm across and 4 mm wide,
# eight straight threads from the centre to the frame, four concentric rings
# of thread, and a small spider in the middle.
param d = 120 mm
param frame_w = 4 mm
param thread = 1.5 mm

solid web {
    # the frame: a ring 120 mm across, 4 mm wide (its hole cuts only the frame)
    solid frame {
        outer = Circle(center=(0, 0), diameter=d)
        hole inside { c = Circle(center=(0, 0), diameter=d - 2 * frame_w) }
        Concentric(inside.c, outer)
    }

    solid threads {
        for i in range(8) {
            t = Stroke(Line((0, 0), (cos(i * 45 deg) * (d / 2 - frame_w / 2), sin(i * 45 deg) * (d / 2 - frame_w / 2))), thread)
        }
        for k in range(4) {
            r = Shell(Circle(center=(0, 0), radius=(k + 1) * (d / 2 - frame_w) / 5), thread)
        }
    }

    solid spider {
        abdomen = Circle(center=(0, -3), radius=4)
        head = Circle(center=(0, 3), radius=2.5)
        for j in range(4) {
            leg_r = Stroke(Polyline([(2, j * 2.5 - 3), (7, j * 3 - 1), (9, j * 4 - 7)]), 1)
            leg_l = Stroke(Polyline([(-2, j * 2.5 - 3), (-7, j * 3 - 1), (-9, j * 4 - 7)]), 1)
        }
    }
}
