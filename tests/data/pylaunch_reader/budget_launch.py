from launch import LaunchDescription


def generate_launch_description():
    total = 0
    for a in range(200):
        for b in range(200):
            for c in range(200):
                total = total + a * b * c
    return LaunchDescription([])
