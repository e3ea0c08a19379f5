from example_interfaces.srv import AddTwoInts
import rclpy
from rclpy.node import Node


class AdderClient(Node):

    def __init__(self):
        super().__init__('adder_client')
        self.cli = self.create_client(srv_type=AddTwoInts, srv_name='add_two_ints')

    def send(self, a, b):
        request = AddTwoInts.Request(a=a, b=b)
        return self.cli.call_async(request)


def main():
    rclpy.init()
    client = AdderClient()
    rclpy.spin_until_future_complete(client, client.send(1, 2))
