from rclpy.node import *
from std_msgs.msg import String


class StarTalker(Node):

    def __init__(self):
        super().__init__('star_talker')
        msg_type = String
        self.create_publisher(msg_type, 'star', 10)
