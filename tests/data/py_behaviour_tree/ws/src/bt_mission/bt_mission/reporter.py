from std_msgs.msg import String


class StatusReporter:
    """A plain helper: it is handed the node when it is built, publishes when asked to."""

    def __init__(self, node, topic='mission/status'):
        self.node = node
        self.topic = topic
        self.publisher = None

    def report(self, text):
        if self.publisher is None:
            self.publisher = self.node.create_publisher(String, self.topic, 10)
        self.publisher.publish(String(data=text))
