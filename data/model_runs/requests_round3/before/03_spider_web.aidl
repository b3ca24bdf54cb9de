# A spider-web wall decoration: a round frame 120 mm across and 4 mm wide (a ring),
# eight straight threads from the centre to the frame, four concentric rings of
# thread, and a small spider in the middle. Cut as one piece.

param frame_d = 120 mm
param frame_w = 4 mm
param thread_w = 1.5 mm
param threads = 8
param rings = 4

frame_r = frame_d / 2
inner_r = frame_r - frame_w     # inside edge of the frame

solid web {
    # the frame: a 4 mm wall inside the 120 mm circle
    rim = Circle(center=(0, 0), radius=inner_r, construction=true)
    frame = Shell(rim, frame_w)
    Fixed(rim)

    # eight radial threads from the centre to the frame (overlapping it a little)
    thread = Rectangle(center=(inner_r / 2 + 0.5, 0), width=inner_r + 1, height=thread_w)
    Fixed(thread)
    spokes = CircularPattern(thread, threads, rim.center)

    # four concentric rings of thread, evenly spaced between the spider and the frame
    for k in range(rings) {
        guide = Circle(center=(0, 0), radius=inner_r * (k + 1) / (rings + 1),
                       construction=true)
        loop = Shell(guide, thread_w)
        Concentric(guide, rim)
    }

    # the spider: body, head and four legs on each side
    solid spider {
        abdomen = Ellipse(center=(0, -3), rx=3.5, ry=4.5)
        head = Circle(center=(0, 3), radius=2.5)
        for j in range(4) {
            leg = Stroke(Polyline([(1, 2 - j * 1.8), (5.5, 4.5 - j * 3), (8, 3 - j * 4.2)]), 1.2)
        }
        legs_left = [Mirrored(l, about=Line((0, -10), (0, 10), construction=true)) for l in leg]
    }
    Rigid(spider)
    CenterInside(spider, rim)
}
