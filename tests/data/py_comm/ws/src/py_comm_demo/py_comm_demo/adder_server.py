import functools

from example_interfaces.srv import AddTwoInts
import rclpy
from rclpy.node import Node
from std_srvs.srv import SetBool


class AdderServer(Node):

    def __init__(self):
        Node.__init__(self, 'adder_server')
        self.srv = self.create_service(AddTwoInts, 'add_two_ints', self.handle_add)
        self.enable = self.create_service(SetBool, 'enable', functools.partial(self.on_enable, source='srv'))

    def handle_add(self, request, response):
        response.sum = request.a + request.b
        return response

    def on_enable(self, request, response, source):
        return response


def main():
    rclpy.init()
    rclpy.spin(AdderServer())
